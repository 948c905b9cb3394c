#!/usr/bin/env python3
"""Writes tests/fuzz/scene.dict, the libFuzzer dictionary for scene files: JSON punctuation, edge-case numbers
and every key, enum value and constant of the scene format's schema (docs/scene.schema.json).
Run it again when the schema changes: python3 tests/fuzz/make_dict.py (a test checks that the file is current)."""
import json
import pathlib

root = pathlib.Path(__file__).resolve().parents[2]
schema = json.loads((root / "docs/scene.schema.json").read_text())


def walk(node, names):
    if isinstance(node, dict):
        for key, value in node.get("properties", {}).items():
            names.add(key)
        for value in node.get("enum", []):
            if isinstance(value, str):
                names.add(value)
        if isinstance(node.get("const"), str):
            names.add(node["const"])
        for value in node.values():
            walk(value, names)
    elif isinstance(node, list):
        for value in node:
            walk(value, names)


names = set()
walk(schema, names)
tokens = ["{", "}", "[", "]", ":", ",", '"', " true", " false", " null", "-1", "0", "1e308", "-0.0", "1e-320"]
lines = ["# libFuzzer dictionary for scene files (written by tests/fuzz/make_dict.py from docs/scene.schema.json)."]
lines += ['"%s"' % t.replace("\\", "\\\\").replace('"', '\\"') for t in tokens]
lines += ['"\\"%s\\""' % name.replace("\\", "\\\\").replace('"', '\\"') for name in sorted(names)]
(root / "tests/fuzz/scene.dict").write_text("\n".join(lines) + "\n")
print(f"tests/fuzz/scene.dict: {len(tokens)} tokens, {len(names)} names")
