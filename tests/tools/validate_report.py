#!/usr/bin/env python3
"""Checks report.json files against docs/reference/report.schema.json (JSON Schema 2020-12).

  validate_report.py FILE...

Exit status 0 when every file fits; otherwise one line per problem, `FILE: <json path>:
<message>`, and exit status 1. Without the jsonschema module (Debian: python3-jsonschema) it
fails too: a check that quietly skips would let reports drift from their documented form."""

import json
import os
import sys

SCHEMA = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "reference",
                                      "report.schema.json"))


class NotJson(ValueError):
    pass


def _strict_object(pairs):
    # The writer never repeats a key; json.load would keep the last one silently.
    keys = [k for k, _ in pairs]
    for k in keys:
        if keys.count(k) > 1:
            raise NotJson("the key %r appears more than once in one object" % k)
    return dict(pairs)


def _no_constant(name):
    # NaN and Infinity are not JSON (the writer writes null for them), though json.load takes them.
    raise NotJson("%s is not JSON" % name)


def _json_path(error):
    path = "$"
    for part in error.absolute_path:
        path += "[%d]" % part if isinstance(part, int) else ".%s" % part
    return path


class Unusable(Exception):
    """The check cannot be made: no jsonschema module, or no usable schema."""


def validator():
    """The schema's validator; Unusable where there is none."""
    try:
        import jsonschema
    except ImportError:
        raise Unusable("the Python module jsonschema is missing (Debian: apt-get install python3-jsonschema; "
                       "scripts/setup.sh installs it), so report.json cannot be checked")
    try:
        with open(SCHEMA, encoding="utf-8") as f:
            schema = json.load(f)
        jsonschema.Draft202012Validator.check_schema(schema)
    except (OSError, ValueError, jsonschema.exceptions.SchemaError) as e:
        raise Unusable("%s is not a usable JSON Schema 2020-12: %s" % (SCHEMA, e))
    return jsonschema.Draft202012Validator(schema)


def problems(path, check=None):
    """Lines `path: <json path>: <message>` for everything wrong with the file; none if it fits."""
    if check is None:
        check = validator()
    try:
        with open(path, encoding="utf-8") as f:
            report = json.load(f, object_pairs_hook=_strict_object, parse_constant=_no_constant)
    except (OSError, ValueError) as e:
        return ["%s: $: not a readable JSON file: %s" % (path, e)]
    errors = sorted(check.iter_errors(report), key=lambda e: (list(map(str, e.absolute_path)), e.message))
    return ["%s: %s: %s" % (path, _json_path(e), e.message) for e in errors]


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        sys.stderr.write(__doc__)
        return 2
    try:
        check = validator()
    except Unusable as e:
        sys.stderr.write("validate_report.py: %s\n" % e)
        return 1
    lines = [line for path in argv for line in problems(path, check)]
    for line in lines:
        print(line)
    return 1 if lines else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
