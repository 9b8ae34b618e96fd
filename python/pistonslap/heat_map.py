"""`pistonslap map DIR --x NAME --y NAME --metric NAME`: a heat map of a sweep's metric, or of the response class,
over two swept variables, from DIR/results.parquet (DIR is the sweep's folder, OUT/<name>).

Points on a full (x, y) grid fill cells; scattered points (a Latin hypercube) are drawn as dots. Failed points
(status not ok) and unclassified ones are grey.
"""

from pathlib import Path

import fmpy
import matplotlib.pyplot as plt
import numpy as np
import pyarrow.compute as pc
import pyarrow.parquet as pq
from matplotlib.colors import ListedColormap

from .fmu import fmu_path
from .refusal import Parser, Refusal, number
from .settings import display_unit, settable, value_of
from .sweep_point import METRICS, all_zero

#: The response classes in the order of their colours.
RESPONSES = ("periodic", "transient chaos", "chaos")
_RESPONSE_COLOURS = ("tab:green", "tab:orange", "tab:red")
_FAILED = "lightgrey"


def _parser():
    parser = Parser(prog="pistonslap map", description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path, help="the sweep's folder (holding results.parquet)")
    parser.add_argument("--x", required=True, help="swept variable along x")
    parser.add_argument("--y", required=True, help="swept variable along y")
    parser.add_argument("--metric", required=True, help=f"one of {', '.join(METRICS)}, or response")
    parser.add_argument(
        "--where",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="keep the points where another swept variable has this value (repeatable)",
    )
    parser.add_argument("--out", type=Path, help="PNG to write (default: DIR/<metric>_<x>_<y>.png)")
    return parser


def _select(table, where, model_description):
    """The rows of `table` where each `NAME=VALUE` of `where` holds (VALUE in SI or a unit the FMU declares)."""
    for condition in where:
        name, _, text = condition.partition("=")
        if name not in table.column_names:
            raise Refusal(f"--where {condition}: no column {name!r}")
        value = (
            value_of(name, text, model_description, f"--where {condition}")
            if name in settable(model_description)
            else number(text, f"--where {condition}")
        )
        kept = table.filter(pc.equal(table[name], pc.cast(value, table[name].type)))
        if kept.num_rows == 0:
            values = ", ".join(f"{v:g}" for v in sorted(set(table[name].to_pylist())))
            raise Refusal(f"--where {condition}: no point has {name} = {value:g} (SI); its values: {values}")
        table = kept
    return table


def _values(table, metric):
    """A metric's values, NaN for failed points."""
    failed = np.array([s != "ok" for s in table["status"].to_pylist()])
    return np.where(failed, np.nan, table[metric].to_numpy(zero_copy_only=False).astype(float))


def _cell_edges(values):
    """Edges of cells centred on the sorted `values` (half-way between neighbours)."""
    if len(values) == 1:
        return np.array([values[0] - 0.5, values[0] + 0.5]) if values[0] == 0 else values[0] * np.array([0.99, 1.01])
    middle = (values[1:] + values[:-1]) / 2
    return np.concatenate([[2 * values[0] - middle[0]], middle, [2 * values[-1] - middle[-1]]])


def heat_map(table, x, y, metric, path, title):
    """Writes the map of `metric` (a METRICS name or 'response') over columns `x`, `y` of `table` to `path`."""
    for name in (x, y):
        if name not in table.column_names:
            raise Refusal(f"no swept variable {name!r} in the results (columns: {', '.join(table.column_names)})")
    if metric != "response" and metric not in METRICS:
        raise Refusal(f"--metric {metric}: give one of {', '.join(METRICS)} or response")
    md = fmpy.read_model_description(str(fmu_path()))
    (x_unit, x_factor), (y_unit, y_factor) = display_unit(x, md), display_unit(y, md)
    xs, ys = table[x].to_numpy().astype(float), table[y].to_numpy().astype(float)
    if metric == "response":
        classes = table["response"].to_pylist()
        values = np.array([RESPONSES.index(c) if c in RESPONSES else np.nan for c in classes], dtype=float)
        cmap, norm = ListedColormap(_RESPONSE_COLOURS), dict(vmin=-0.5, vmax=len(RESPONSES) - 0.5)
    else:
        values = _values(table, metric)
        cmap, norm = plt.get_cmap("viridis"), {}
    cmap = cmap.with_extremes(bad=_FAILED)

    fig, ax = plt.subplots(figsize=(7, 5.5))
    grid_x, grid_y = np.unique(xs), np.unique(ys)
    cells = set(zip(xs, ys, strict=True))
    if len(cells) == len(xs) == len(grid_x) * len(grid_y):
        image = np.full((len(grid_y), len(grid_x)), np.nan)
        image[np.searchsorted(grid_y, ys), np.searchsorted(grid_x, xs)] = values
        artist = ax.pcolormesh(
            _cell_edges(grid_x) * x_factor,
            _cell_edges(grid_y) * y_factor,
            np.ma.masked_invalid(image),
            cmap=cmap,
            **norm,
        )
    elif len(cells) == len(xs):
        artist = ax.scatter(
            xs * x_factor, ys * y_factor, c=np.ma.masked_invalid(values), cmap=cmap, plotnonfinite=True, s=60, **norm
        )
    else:
        raise Refusal(
            f"several points share an ({x}, {y}) pair: other variables vary; pick one value of each "
            "with --where NAME=VALUE"
        )
    if metric != "response" and all_zero(values):
        ax.text(
            0.5,
            0.5,
            f"{metric} is 0 at every point",
            transform=ax.transAxes,
            ha="center",
            va="center",
            fontsize="large",
            bbox=dict(fc="white", ec="0.5"),
        )
    bar = fig.colorbar(artist, ax=ax)
    if metric == "response":
        bar.set_ticks(range(len(RESPONSES)), labels=RESPONSES)
        bar.set_label("response (grey: failed or not classified)")
    else:
        bar.set_label(f"{metric} [{METRICS[metric]}] (grey: failed)")
    ax.set_xlabel(f"{x} [{x_unit}]")
    ax.set_ylabel(f"{y} [{y_unit}]")
    ax.set_title(title, fontsize="medium")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def main(argv=None):
    args = _parser().parse_args(argv)
    results = args.folder / "results.parquet"
    if not results.exists():
        raise Refusal(f"{results} is missing: run the sweep (pistonslap sweep SPEC --out ...) into it first")
    if args.out is not None and (args.out.suffix.lower() != ".png" or args.out.is_dir()):
        raise Refusal(f"--out {args.out}: give the name of a .png file")
    table = _select(pq.read_table(results), args.where, fmpy.read_model_description(str(fmu_path())))
    out = args.out or args.folder / f"{args.metric}_{args.x}_{args.y}.png"
    condition = f" ({', '.join(args.where)})" if args.where else ""
    print(f"wrote {heat_map(table, args.x, args.y, args.metric, out, f'{args.folder.name}: {args.metric}{condition}')}")
    if args.metric in METRICS and all_zero(_values(table, args.metric)):
        print(f"{args.metric} is 0 at every point drawn: the map is one colour")
