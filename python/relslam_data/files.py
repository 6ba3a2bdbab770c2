"""Checked readers for the files relslam writes: CSV, TUM trajectories and JSON.

pandas reads a CSV whose last row was cut short (a killed run, a full disk) without complaint,
padding the missing fields with NaN; a plot of such a file silently shows a wrong curve. These
readers refuse instead, raising DataError with the file and the problem, so a damaged folder
is reported once, by name, rather than as a traceback or a misleading figure.
"""
import csv
import io
import json
from pathlib import Path

import pandas as pd

NAN_SPELLINGS = ["", "nan", "-nan", "NaN", "-NaN"]
TUM_COLUMNS = ["t", "x", "y", "z", "qx", "qy", "qz", "qw"]


class DataError(ValueError):
    """A file of a run or sweep folder is missing or damaged. str(e) reads "PATH: PROBLEM"."""

    def __init__(self, path, problem):
        super().__init__(f"{path}: {problem}")
        self.path = Path(path)
        self.problem = problem


def _read_text(path):
    """The file's text; DataError if it is missing, unreadable or cut mid-line.

    relslam ends every file with a newline, so text that does not is a write that stopped."""
    path = Path(path)
    if not path.is_file():
        raise DataError(path, "file not found")
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise DataError(path, f"cannot read: {e}") from None
    if text and not text.endswith("\n"):
        raise DataError(path, "cut short: the last line has no newline (was the run stopped?)")
    return text


def read_csv(path, required=(), numeric=(), strings=()):
    """The CSV as a DataFrame, checked: a header, every row as long as the header, the `required`
    columns present and the `numeric` ones numbers (empty fields are NaN). `numeric` is a list of
    names or a test on a column name (for tables whose columns depend on the run). The `strings`
    columns stay strings as written even where they look like numbers (a sweep axis's "0.10",
    a list of plane ids "3"); their empty fields are NaN too.

    Checking the field count row by row is what catches a cut file; pandas would pad it."""
    text = _read_text(path)
    rows = csv.reader(io.StringIO(text))
    header = next(rows, None)
    if not header:
        raise DataError(path, "empty file (no header line)")
    for line, row in enumerate(rows, start=2):
        if len(row) != len(header):
            raise DataError(path, f"line {line}: {len(row)} fields, the header has {len(header)}")
    missing = [c for c in required if c not in header]
    if missing:
        raise DataError(path, f"missing column(s) {', '.join(missing)}")
    # Text columns (algorithm, status, folder, an axis's labels) stay as written: keep_default_na=False
    # stops pandas from turning a label such as "None" or "NA" into NaN; empty fields and C++'s
    # spellings of not-a-number are NaN. Numbers are read exactly as Python's float() reads them
    # (round_trip): pandas' faster default may be one unit in the last place off, enough to change a
    # difference of two nearly equal numbers.
    frame = pd.read_csv(io.StringIO(text), keep_default_na=False, na_values=NAN_SPELLINGS, float_precision="round_trip",
                        dtype={c: str for c in strings if c in header} or None)
    is_numeric = numeric if callable(numeric) else lambda name: name in numeric
    for column in filter(is_numeric, frame.columns):
        if not pd.api.types.is_numeric_dtype(frame[column]):
            converted = pd.to_numeric(frame[column], errors="coerce")
            bad = frame[column][converted.isna() & frame[column].notna()]
            if len(bad):
                line = int(bad.index[0]) + 2
                raise DataError(path, f"line {line}: column {column}: not a number: {bad.iloc[0]!r}")
            frame[column] = converted  # a header without rows reads as text: no row is wrong
    return frame


def read_tum(path):
    """A TUM trajectory (t x y z qx qy qz qw per line, '#' comments) as a DataFrame with those
    column names; evo and relslam both write this format."""
    text = _read_text(path)
    values = []
    for line, content in enumerate(text.splitlines(), start=1):
        if not content.strip() or content.startswith("#"):
            continue
        fields = content.split()
        if len(fields) != len(TUM_COLUMNS):
            raise DataError(path, f"line {line}: {len(fields)} fields, a TUM line has {len(TUM_COLUMNS)}")
        try:
            values.append([float(f) for f in fields])
        except ValueError:
            raise DataError(path, f"line {line}: not a number in {content!r}") from None
    return pd.DataFrame(values, columns=TUM_COLUMNS, dtype=float)


def read_json(path):
    """The JSON document (manifest.json, plan.json) as Python objects."""
    text = _read_text(path)
    try:
        return json.loads(text)
    except json.JSONDecodeError as e:
        raise DataError(path, f"not valid JSON: {e}") from None


def scenario_name(manifest, folder):
    """The scenario's name a manifest.json records, else the folder's name (also for a run without a
    scenario file, whose manifest says "(defaults)")."""
    scenario = manifest.get("scenario")
    if isinstance(scenario, dict) and scenario.get("name") and not str(scenario["name"]).startswith("("):
        return scenario["name"]
    return Path(folder).name
