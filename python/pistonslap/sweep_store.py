"""A sweep's folder: its spec, the parquet part written for each finished batch, and the merged results.

DIR/<name>/spec.json        the spec the results belong to (a rerun with another spec is refused)
DIR/<name>/parts/*.parquet  one per finished batch, each written whole (to a temporary name, then renamed)
DIR/<name>/results.parquet  every recorded point, one row each, by point index
"""

import json
import os
import uuid
from dataclasses import asdict
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq

from .sweep_point import METRICS
from .sweep_spec import SpecError

_ARROW = {bool: pa.bool_(), int: pa.int64(), float: pa.float64(), str: pa.string()}


class Store:
    """The results folder of `spec` under `out`; refuses a folder holding another spec's results."""

    def __init__(self, out, spec):
        self.folder = Path(out) / spec.name
        self.parts = self.folder / "parts"
        self.results = self.folder / "results.parquet"
        self.parts.mkdir(parents=True, exist_ok=True)
        recorded = self.folder / "spec.json"
        # the metrics' names too: results of a version with other columns cannot be merged with these
        identity = json.dumps(dict(asdict(spec), metrics=list(METRICS)), sort_keys=True)
        if recorded.exists() and recorded.read_text() != identity:
            raise SpecError(
                f"{self.folder} holds the results of another spec named {spec.name!r} (or of a version of pistonslap "
                "with other columns): give another --out or name, or remove the folder"
            )
        recorded.write_text(identity)
        self.schema = pa.schema(
            [("point", pa.int64())]
            + [(name, _ARROW[type(value)]) for name, value in spec.points[0].items()]
            + [(name, pa.float64()) for name in METRICS]
            + [("response", pa.string()), ("period", pa.int64()), ("settled", pa.int64()), ("status", pa.string())]
        )

    def write_part(self, rows):
        """Records finished points (dicts with every column) as one part file, atomically."""
        part = self.parts / f"part-{uuid.uuid4().hex}.parquet"
        temporary = part.with_suffix(".tmp")
        pq.write_table(pa.Table.from_pylist(rows, schema=self.schema), temporary)
        os.replace(temporary, part)

    def read(self):
        """Every recorded point: the merged results, then the parts' rows of points they lack, by point index."""
        tables = [pq.read_table(self.results, schema=self.schema)] if self.results.exists() else []
        merged = {p for table in tables for p in table["point"].to_pylist()}
        for part in sorted(self.parts.glob("*.parquet")):
            table = pq.read_table(part, schema=self.schema)
            # a part merged into the results by a run that died before removing it
            fresh = [p not in merged for p in table["point"].to_pylist()]
            tables.append(table.filter(pa.array(fresh, type=pa.bool_())))
        table = pa.concat_tables(tables) if tables else self.schema.empty_table()
        return table.sort_by("point")

    def done(self):
        """The indices of the recorded points."""
        return set(self.read()["point"].to_pylist())

    def merge(self):
        """Writes every recorded point to results.parquet (atomically), then removes the parts; returns its path."""
        table = self.read()
        temporary = self.results.with_suffix(".tmp")
        pq.write_table(table, temporary)
        os.replace(temporary, self.results)
        for part in self.parts.glob("*.parquet"):
            part.unlink()
        return self.results
