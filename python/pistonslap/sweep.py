"""Runs a sweep spec on Dask: `pistonslap sweep SPEC.toml [--workers N | --scheduler ADDRESS] [--out DIR]`.

The FMU travels once, in a worker plugin that each worker (a restarted one too) extracts to its local directory
and keeps; a task carries only a batch of points and the spec's fixed settings, and returns their rows. The client
writes each finished batch as a parquet part, so a rerun runs only the points not recorded yet.
"""

import dataclasses
import math
import os
import sys
import tempfile
from pathlib import Path

import fmpy
import pyarrow.parquet as pq
from distributed import Client, LocalCluster, as_completed, get_worker
from distributed.diagnostics.plugin import WorkerPlugin
from tqdm import tqdm

from .fmu import fmu_path
from .refusal import Parser, Refusal
from .sweep_point import METRICS, all_zero, run_point, zero_note
from .sweep_spec import SpecError, load
from .sweep_store import Store
from .trace_tdc import PlacedTrace

#: Batches per worker when the batch size is left to the sweep: enough to balance uneven run times, few enough
#: that a task's overhead (milliseconds) stays small against its runs.
BATCHES_PER_WORKER = 10
MAX_BATCH = 100


class FmuPlugin(WorkerPlugin):
    """The FMU's bytes, extracted once per worker; `folder` and `model_description` serve every task there."""

    name = "pistonslap-fmu"

    def __init__(self, fmu_bytes):
        self.fmu_bytes = fmu_bytes

    def setup(self, worker):
        self.folder = Path(worker.local_directory) / self.name
        with tempfile.NamedTemporaryFile(suffix=".fmu") as f:
            f.write(self.fmu_bytes)
            f.flush()
            fmpy.extract(f.name, unzipdir=self.folder)
        self.model_description = fmpy.read_model_description(self.folder)


def run_batch(points, fixed, cycles, skip_cycles):
    """The rows of `points` ((index, swept values) pairs), run on this worker's extracted FMU."""
    fmu = get_worker().plugins[FmuPlugin.name]
    return [
        dict(
            point=index,
            **values,
            **run_point(fmu.folder, fmu.model_description, dict(fixed, **values), cycles, skip_cycles),
        )
        for index, values in points
    ]


def run(spec, out, client, fmu=None, batch_size=None, progress=True):
    """Runs the points of `spec` not yet recorded under `out` on `client`'s workers and merges the results;
    returns (path of results.parquet, number of points run now)."""
    store = Store(out, spec)
    todo = sorted(set(range(len(spec.points))) - store.done())
    if todo:
        client.register_plugin(FmuPlugin(Path(fmu or fmu_path()).read_bytes()))
        workers = max(len(client.scheduler_info(n_workers=-1)["workers"]), 1)
        size = batch_size or min(max(math.ceil(len(todo) / (BATCHES_PER_WORKER * workers)), 1), MAX_BATCH)
        futures = [
            client.submit(
                run_batch,
                [(i, spec.points[i]) for i in todo[k : k + size]],
                spec.fixed,
                spec.cycles,
                spec.skip_cycles,
                pure=False,
            )
            for k in range(0, len(todo), size)
        ]
        with tqdm(
            total=len(spec.points),
            initial=len(spec.points) - len(todo),
            unit="point",
            disable=not progress,
            desc=spec.name,
            file=sys.stderr,
        ) as bar:
            for future in as_completed(futures):
                rows = future.result()
                store.write_part(rows)
                bar.update(len(rows))
    return store.merge(), len(todo)


def _parser():
    parser = Parser(prog="pistonslap sweep", description=__doc__.splitlines()[0])
    parser.add_argument("spec", type=Path, help="the sweep's TOML spec")
    where = parser.add_mutually_exclusive_group()
    where.add_argument(
        "--workers",
        type=int,
        default=os.cpu_count(),
        help="worker processes of a local cluster, one thread each (default: all cores)",
    )
    where.add_argument("--scheduler", help="address of a running Dask scheduler (tcp://host:8786) to use instead")
    parser.add_argument("--out", type=Path, default=Path("out/sweeps"), help="results folder (default out/sweeps)")
    parser.add_argument("--batch", type=int, help="points per task (default: about ten tasks per worker)")
    return parser


def connect(workers, scheduler):
    """A client of the scheduler at `scheduler`, else of a new local cluster of `workers` single-thread processes."""
    if scheduler:
        return Client(scheduler)
    return Client(LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None))


def summary(path, ran):
    """One line on the results at `path`: points, run now, failed, and the first failure's point and message; then a
    line naming the metrics that read 0 at every point, if any."""
    table = pq.read_table(path)
    failed = [(p, s) for p, s in zip(table["point"].to_pylist(), table["status"].to_pylist(), strict=True) if s != "ok"]
    line = f"wrote {path} ({table.num_rows} points, {ran} run now, {len(failed)} failed"
    line += f"; first failure: point {failed[0][0]}: {failed[0][1]})" if failed else ")"
    zeros = [name for name in METRICS if name in table.column_names and all_zero(table[name].to_numpy())]
    note = zero_note(zeros)
    return line + (f"\n{note}" if note else "")


def with_trace(spec, out):
    """`spec` with its pressure traces where they run (pressure_source = 3), the [start] one and a [grid]'s, read as
    exported, all refused with the file's line before anything runs, and written in the FMU's own form into the
    results' folder, where the workers read them: the [start] one as `pressure_trace_as_run.csv`, a [grid]'s each
    numbered and named after its file."""
    fixed = spec.fixed

    def runs(values):
        merged = dict(fixed, **values)
        return merged.get("pressure_source") == 3 and bool(merged.get("pressure_trace"))

    start = [fixed["pressure_trace"]] if "pressure_trace" in fixed and runs({}) else []
    swept = [p["pressure_trace"] for p in spec.points if "pressure_trace" in p and runs(p)]
    paths = list(dict.fromkeys(start + swept))
    if not paths:
        return spec
    placed = [PlacedTrace(path, None, fmu_path()) for path in paths]
    folder = Path(out) / spec.name
    folder.mkdir(parents=True, exist_ok=True)
    written = {}
    for k, (path, trace) in enumerate(zip(paths, placed, strict=True)):
        print(trace.said)
        name = "pressure_trace_as_run.csv" if start and k == 0 else f"{k}_{Path(path).stem}_as_run.csv"
        written[path] = trace.write(folder, name)

    def as_run(values):
        trace = values.get("pressure_trace")
        return dict(values, pressure_trace=written[trace]) if trace in written else values

    return dataclasses.replace(spec, fixed=as_run(fixed), points=[as_run(p) for p in spec.points])


def main(argv=None):
    args = _parser().parse_args(argv)
    if args.batch is not None and args.batch < 1:
        raise Refusal(f"--batch = {args.batch}: give at least 1")
    if args.scheduler is None and args.workers < 1:
        raise Refusal(f"--workers = {args.workers}: give at least 1")
    if not args.spec.is_file():
        raise Refusal(f"{args.spec}: no such spec file")
    try:
        spec = load(args.spec, fmpy.read_model_description(str(fmu_path())))
        spec = with_trace(spec, args.out)
        with connect(args.workers, args.scheduler) as client:
            path, ran = run(spec, args.out, client, batch_size=args.batch)
    except SpecError as e:
        raise Refusal(f"{args.spec}: {e}") from None
    print(summary(path, ran))
