#!/usr/bin/env python3
"""The house's size rules (issue 19): non-test lines per Rust source file
(at most about 500) and lines per function (at most about 80). Prints the
files and functions over the limits, largest first; exits 1 when any is.
usage: python3 scripts/size-check.py [FILE_LIMIT [FN_LIMIT]]"""
import re
import subprocess
import sys

file_limit = int(sys.argv[1]) if len(sys.argv) > 1 else 500
fn_limit = int(sys.argv[2]) if len(sys.argv) > 2 else 80
files = subprocess.run(["git", "ls-files", "crates/*.rs"], capture_output=True, text=True).stdout.split()
files = [f for f in files if "/src/" in f]
big_files, big_fns = [], []
for f in files:
    text = open(f, encoding="utf-8").read()
    # Non-test code: everything before the test module (a `#[cfg(test)]`
    # item elsewhere, such as a test-only helper, does not end the count).
    m = re.search(r"^#\[cfg\(test\)\]\s*\n\s*mod \w+", text, re.M)
    code = text if m is None else text[: m.start()]
    lines = code.split("\n")
    if len(lines) > file_limit:
        big_files.append((len(lines), f))
    # A function: a line that opens `fn name(` (any visibility), up to the
    # line that closes its body at the same indentation.
    for i, line in enumerate(lines):
        m = re.match(r"^(\s*)(?:pub(?:\([^)]*\))?\s+)?(?:const\s+)?(?:async\s+)?(?:unsafe\s+)?fn\s+(\w+)", line)
        if not m:
            continue
        indent = m.group(1)
        for j in range(i, len(lines)):
            if lines[j].rstrip().endswith(";") and j == i:
                break  # a declaration without a body
            if lines[j] == indent + "}":
                if j - i + 1 > fn_limit:
                    big_fns.append((j - i + 1, f"{f}:{i + 1} {m.group(2)}"))
                break
for n, f in sorted(big_files, reverse=True):
    print(f"file {n:5d} lines  {f}")
for n, f in sorted(big_fns, reverse=True):
    print(f"fn   {n:5d} lines  {f}")
print(f"{len(big_files)} files over {file_limit} non-test lines, {len(big_fns)} functions over {fn_limit} lines")
sys.exit(1 if big_files or big_fns else 0)
