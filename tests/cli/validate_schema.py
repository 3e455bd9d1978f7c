#!/usr/bin/env python3
"""The shipped lattice files validate against the shipped JSON Schema, and the
schema rejects a few bad files (so that it is not vacuous)."""
import json
import pathlib
import sys

import jsonschema

folder = pathlib.Path(sys.argv[1])
schema = json.loads((folder / "lattice.schema.json").read_text())
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
passed = failed = 0
for path in sorted(folder.glob("*.json")) + sorted(folder.glob("examples/*.json")):
    if path.name == "lattice.schema.json":
        continue
    errors = list(validator.iter_errors(json.loads(path.read_text())))
    if errors:
        print(f"FAIL: {path.name}: {errors[0].message}")
        failed += 1
    else:
        passed += 1
bad = [
    {"name": "x", "dimension": 2, "basis": [[1, 0], [0, 1]]},
    {"name": "x", "dimension": 4, "basis": [[1, 0], [0, 1]], "motif": [[0, 0]]},
    {"name": "x", "dimension": 2, "basis": [[1, 0, 0], [0, 1, 0]], "motif": [[0, 0]]},
    {"name": "x", "dimension": 2, "basis": [[1, 0], [0, 1]], "motif": [[0, 0]], "gravty": [0, -1]},
    {"name": "x", "dimension": 2, "basis": [[1, 0], [0, 1]], "motif": [[0, 0]], "volume_coefficients": {"voronoi": 1}},
]
for doc in bad:
    if validator.is_valid(doc):
        print(f"FAIL: the schema accepts {doc}")
        failed += 1
    else:
        passed += 1
print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
