#!/usr/bin/python3
"""Validates a dgwarp --json report against its schema in docs/schema/.

Usage: check_json_schema.py SCHEMA_DIR COMMAND [REPORT.json]

Reads the report from REPORT.json, or from standard input when it is absent
or "-", and validates it against SCHEMA_DIR/COMMAND.schema.json (JSON Schema
draft 2020-12) with Debian's python3-jsonschema. The schemas refer to each
other by their $id (https://schema.dgwarp.invalid/2/NAME.schema.json); every
*.schema.json file in SCHEMA_DIR is loaded, nothing is fetched.

Checks first that every schema in SCHEMA_DIR is itself a valid draft 2020-12
schema. Exits 0 when the report is valid, 1 with every violation (path and
message) on stderr when it is not, 2 on bad usage or an unreadable file.
"""
import json
import pathlib
import sys

import jsonschema


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    schema_dir = pathlib.Path(argv[1])
    command = argv[2]
    try:
        store = {}
        for path in sorted(schema_dir.glob("*.schema.json")):
            schema = json.loads(path.read_text(encoding="utf-8"))
            jsonschema.Draft202012Validator.check_schema(schema)
            store[schema["$id"]] = schema
        schema = json.loads((schema_dir / (command + ".schema.json")).read_text(encoding="utf-8"))
        text = sys.stdin.read() if len(argv) == 3 or argv[3] == "-" else pathlib.Path(argv[3]).read_text(encoding="utf-8")
    except (OSError, ValueError, jsonschema.SchemaError) as e:
        print("check_json_schema: %s" % e, file=sys.stderr)
        return 2
    try:
        report = json.loads(text)
    except ValueError as e:
        print("check_json_schema: the report is not JSON: %s" % e, file=sys.stderr)
        return 1
    resolver = jsonschema.RefResolver(schema["$id"], schema, store=store)
    validator = jsonschema.Draft202012Validator(schema, resolver=resolver,
                                                format_checker=jsonschema.FormatChecker())
    errors = sorted(validator.iter_errors(report), key=lambda e: list(e.absolute_path))
    for e in errors:
        if e.context:  # oneOf / anyOf: the closest alternative says more
            e = jsonschema.exceptions.best_match(e.context)
        where = "/".join(str(p) for p in e.absolute_path) or "(top level)"
        print("%s: %s" % (where, e.message), file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
