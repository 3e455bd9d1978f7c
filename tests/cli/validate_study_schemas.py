#!/usr/bin/env python3
"""The shipped studies validate against share/schemas/study.schema.json; documents the
schema rejects are refused by sphkern too (exit 3), so the schema never promises what the
program refuses to read and is not vacuous; with RESULTS files, each validates against
share/schemas/results.schema.json.
Usage: validate_study_schemas.py SCHEMA_DIR STUDY_DIR SPHKERN [RESULTS.json ...]"""
import json
import pathlib
import subprocess
import sys
import tempfile

import jsonschema

schemas, studies, sphkern = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), sys.argv[3]
study_schema = json.loads((schemas / "study.schema.json").read_text())
results_schema = json.loads((schemas / "results.schema.json").read_text())
results_schema["properties"]["study"] = study_schema  # the one cross-file reference, resolved here
for schema in (study_schema, results_schema):
    jsonschema.Draft202012Validator.check_schema(schema)
study_validator = jsonschema.Draft202012Validator(study_schema)
passed = failed = 0


def verdict(ok, message):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL:", message)


for path in sorted(studies.glob("*.json")):
    errors = list(study_validator.iter_errors(json.loads(path.read_text())))
    verdict(not errors, f"{path.name}: {errors[0].message if errors else ''}")

good = {"name": "s", "kernels": ["cubic_bspline"], "lattices": ["triangular"], "k": {"samples": 11}}
bad = [
    {"kernels": ["cubic_bspline"], "lattices": ["fcc"]},
    dict(good, name="Has Spaces"),
    dict(good, kernels=[]),
    dict(good, kernels=[{"kernel": "cubic_bspline", "set": {"x": "one"}}]),
    dict(good, epsilon=1.5),
    dict(good, k={"min": 0.8, "max": 1.2, "axis": "h"}),
    dict(good, sites=[-1]),
    dict(good, modes=[{"name": "paper", "shells": {"2": ["cbrt(3)"]}}]),
    dict(good, surface={"forms": ["up"]}),
    dict(good, stability={"gamma": 0}),
    dict(good, stability={"k": {"min": 0.9}}),
    dict(good, stability={"grid": 1}),
    dict(good, stability={"dispersion_k": "worst"}),
    dict(good, unknown=1),
    dict(good, particles={"sources": [{"lattice": "fcc"}]}),
    dict(good, particles={"sources": [{"poisson": 3, "count": 100, "lattice": "fcc"}]}),
    dict(good, particles={"sources": [{"poisson": 4, "count": 100}]}),
    dict(good, particles={"sources": [{"file": "x.csv"}], "nh": {"min": 0, "max": 10}}),
    dict(good, particles={"sources": [{"file": "x.csv"}], "nh": {"min": 1, "max": 10}, "h_over_l": {"min": 1, "max": 2}}),
    dict(good, particles={"sources": [{"file": "x.csv"}], "volume": "cells"}),
]
verdict(study_validator.is_valid(good), "the schema rejects a minimal good study")
with tempfile.TemporaryDirectory() as work:
    for i, doc in enumerate([good] + bad):
        verdict(i == 0 or not study_validator.is_valid(doc), f"the schema accepts {doc}")
        file = pathlib.Path(work) / f"s{i}.json"
        file.write_text(json.dumps(doc))
        run = subprocess.run([sphkern, "run", str(file), "--no-plots", "-o", f"{work}/out{i}"],
                             capture_output=True, text=True)
        expected = 0 if i == 0 else 3
        verdict(run.returncode == expected, f"sphkern run {doc}: exit {run.returncode}, expected {expected}: {run.stderr.strip()}")



def trimmed(value, keep=40):
    """The document with every array longer than `keep` cut to its first and last keep / 2 items:
    the schema types the items of an array alike, and a whole pass over the results of the
    studies here (5 MB of curves) took 18 s of the suite."""
    if isinstance(value, dict):
        return {k: trimmed(v, keep) for k, v in value.items()}
    if isinstance(value, list):
        items = value if len(value) <= keep else value[:keep // 2] + value[-keep // 2:]
        return [trimmed(v, keep) for v in items]
    return value


def finite_only(constant):
    raise ValueError(f"a non-finite number ({constant}) in a results file")


results_validator = jsonschema.Draft202012Validator(results_schema)
for path in sys.argv[4:]:
    # Every number of the whole file is read (none may be non-finite); the schema sees it trimmed.
    errors = list(results_validator.iter_errors(trimmed(json.loads(pathlib.Path(path).read_text(),
                                                                    parse_constant=finite_only))))
    verdict(not errors, f"{path}: {errors[0].json_path if errors else ''}: {errors[0].message[:300] if errors else ''}")
print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
