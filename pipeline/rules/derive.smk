# Per paper ({paper} wildcard): the SymPy derivations, computed once and pickled (derive), then
# checked against the printed equations (equation audit) and against the committed generated
# code (codegen check), both from that one artefact; and the executed notebook, which preloads
# the derivations derive computed on the way (derivation_memo.pkl, derivations/memo.py).


rule derive:
    input:
        code=derive_code("derive"),
    output:
        kept(f"{RESULTS}/{{paper}}/derivation.pkl"),
        memo=kept(f"{RESULTS}/{{paper}}/derivation_memo.pkl"),
    log:
        f"{RESULTS}/{{paper}}/logs/derive.log",
    benchmark:
        f"{RESULTS}/{{paper}}/benchmarks/derive.tsv"
    priority: job_priority(f"{RESULTS}/{{paper}}/benchmarks/derive.tsv")
    conda:
        ENV
    threads: job_threads(f"{RESULTS}/{{paper}}/benchmarks/derive.tsv")
    resources:
        **job_resources(f"{RESULTS}/{{paper}}/benchmarks/derive.tsv"),
    params:
        audit=lambda wildcards: PAPERS[wildcards.paper].audit_module,
        generator=lambda wildcards: PAPERS[wildcards.paper].generator_module,
    script:
        "../scripts/derive.py"


# the shared frames module (pipeline/generated/frames.py), which every paper's code calls:
# derived once for all papers
rule derive_frames:
    input:
        code=code("derivations.generate_frames", script="derive_frames.py"),
    output:
        kept(f"{RESULTS}/frames_derivation.pkl"),
    log:
        f"{RESULTS}/logs/derive_frames.log",
    benchmark:
        f"{RESULTS}/benchmarks/derive_frames.tsv"
    priority: job_priority(f"{RESULTS}/benchmarks/derive_frames.tsv")
    conda:
        ENV
    threads: job_threads(f"{RESULTS}/benchmarks/derive_frames.tsv")
    resources:
        **job_resources(f"{RESULTS}/benchmarks/derive_frames.tsv"),
    script:
        "../scripts/derive_frames.py"


rule codegen_check:
    input:
        code=derive_code("codegen"),
        derivation=rules.derive.output[0],
        frames_derivation=rules.derive_frames.output[0],
        generated="pipeline/generated/{paper}.py",
        frames="pipeline/generated/frames.py",
    output:
        kept(f"{RESULTS}/{{paper}}/codegen_check.txt"),
    log:
        f"{RESULTS}/{{paper}}/logs/codegen_check.log",
    benchmark:
        f"{RESULTS}/{{paper}}/benchmarks/codegen_check.tsv"
    priority: job_priority(f"{RESULTS}/{{paper}}/benchmarks/codegen_check.tsv")
    conda:
        ENV
    threads: job_threads(f"{RESULTS}/{{paper}}/benchmarks/codegen_check.tsv")
    resources:
        **job_resources(f"{RESULTS}/{{paper}}/benchmarks/codegen_check.tsv"),
    script:
        "../scripts/codegen_check.py"


rule audit:
    input:
        code=derive_code("audit"),
        derivation=rules.derive.output[0],
    output:
        csv=report(
            kept(f"{RESULTS}/{{paper}}/equation_audit.csv"),
            caption=f"{CAPTIONS}/audit.rst",
            category="{paper}",
            subcategory="Equation audit",
        ),
        math=kept(f"{RESULTS}/{{paper}}/equation_math.json"),
    log:
        f"{RESULTS}/{{paper}}/logs/audit.log",
    benchmark:
        f"{RESULTS}/{{paper}}/benchmarks/audit.tsv"
    priority: job_priority(f"{RESULTS}/{{paper}}/benchmarks/audit.tsv")
    conda:
        ENV
    threads: job_threads(f"{RESULTS}/{{paper}}/benchmarks/audit.tsv")
    resources:
        **job_resources(f"{RESULTS}/{{paper}}/benchmarks/audit.tsv"),
    script:
        "../scripts/equation_audit.py"


rule notebook:
    input:
        notebook_code,
        code=code(script="execute_notebook.py"),
        notebook="notebooks/{paper}.ipynb",
        memo=rules.derive.output.memo,
    output:
        report(
            kept(f"{REPORTS}/notebooks/{{paper}}.html"),
            caption=f"{CAPTIONS}/notebook.rst",
            category="{paper}",
            subcategory="Pages",
        ),
    log:
        f"{RESULTS}/{{paper}}/logs/notebook.log",
    benchmark:
        f"{RESULTS}/{{paper}}/benchmarks/notebook.tsv"
    priority: job_priority(f"{RESULTS}/{{paper}}/benchmarks/notebook.tsv")
    conda:
        ENV
    threads: job_threads(f"{RESULTS}/{{paper}}/benchmarks/notebook.tsv")
    resources:
        **job_resources(f"{RESULTS}/{{paper}}/benchmarks/notebook.tsv"),
    script:
        "../scripts/execute_notebook.py"
