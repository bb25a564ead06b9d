# Snakemake script: Figs 2-12 of the altimeter-attitude paper and our filter comparison.
import sys
from pathlib import Path

from pipeline.altimeter_attitude.figures import published_rms, write_all
from pipeline.config import load_yaml

with open(snakemake.log[0], "w") as log:
    sys.stderr = log
    outputs = [Path(p) for p in snakemake.output]
    out_dir = outputs[0].parent
    elsewhere = [str(p) for p in outputs if p.parent != out_dir]
    if elsewhere:
        raise ValueError(f"figure outputs must share one directory ({out_dir}): {elsewhere}")
    truth, timeseries = Path(snakemake.input.truth), Path(snakemake.input.timeseries)
    scenario_dir = truth.parent
    if (truth.name, timeseries.name) != ("truth.csv", "timeseries.csv") or (
        timeseries.parent != scenario_dir
    ):
        raise ValueError(
            f"expected <scenario>/truth.csv and <scenario>/timeseries.csv, got {truth}, {timeseries}"
        )
    published = published_rms(load_yaml(snakemake.input.published))
    print(f"published RMS values: {published}", file=log)
    pngs = [p.name for p in outputs if p.suffix == ".png"]
    written = write_all(scenario_dir, out_dir, published, names=pngs)  # PNG and SVG each
    if sorted(written) != sorted(outputs):
        raise ValueError(f"wrote {sorted(map(str, written))}, outputs {sorted(map(str, outputs))}")
    for path in written:
        print(path, file=log)
