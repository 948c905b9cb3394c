#!/usr/bin/env python3
"""Writes tests/fuzz/scene.dict, the libFuzzer dictionary for scene files: JSON punctuation, edge-case numbers
and every key and enum value the scene format documents (the backticked names of docs/scene-format.md).
Run it again when keys are added: python3 tests/fuzz/make_dict.py"""
import pathlib
import re

root = pathlib.Path(__file__).resolve().parents[2]
names = set(re.findall(r'`"?([a-z][a-z0-9_]*(?:/[0-9])?)"?`', (root / "docs/scene-format.md").read_text()))
tokens = ["{", "}", "[", "]", ":", ",", '"', " true", " false", " null", "-1", "0", "1e308", "-0.0", "1e-320"]
lines = ["# libFuzzer dictionary for scene files (written by tests/fuzz/make_dict.py from docs/scene-format.md)."]
lines += ['"%s"' % t.replace("\\", "\\\\").replace('"', '\\"') for t in tokens]
lines += ['"\\"%s\\""' % name for name in sorted(names)]
(root / "tests/fuzz/scene.dict").write_text("\n".join(lines) + "\n")
print(f"tests/fuzz/scene.dict: {len(tokens)} tokens, {len(names)} names")
