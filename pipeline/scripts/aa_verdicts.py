# Snakemake script: verdicts of the altimeter-attitude paper (published scenario's results).
from pathlib import Path

from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.altimeter_attitude.verdicts import load_published, verdicts
from pipeline.atomic import write_csv
from pipeline.columns import VERDICT_COLUMNS

with open(snakemake.log[0], "w") as log:  # noqa: F821
    published = load_published(snakemake.input.published)  # noqa: F821
    sc = load_scenario(snakemake.input.scenario)  # noqa: F821
    frame = verdicts(published, Path(snakemake.input.results[0]).parent, sc.transient)  # noqa: F821
    write_csv(snakemake.output[0], frame, VERDICT_COLUMNS)  # noqa: F821
    print(frame["verdict"].value_counts().to_string(), file=log)
