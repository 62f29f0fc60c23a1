#!/usr/bin/env python3
"""Check the README and the docs: links resolve, the user guide's examples run.

    python3 scripts/check-guide.py SNOWROLL [--python PY]

1. Every relative Markdown link of README.md, bench/README.md and docs/**/*.md
   names a file that exists in the repository, and a `#fragment` names a
   heading of the target (GitHub's anchor rule: lower case, punctuation
   dropped, spaces to hyphens).
2. Every line of a ```sh block of docs/guide/*.md that starts with
   `snowroll ` runs with SNOWROLL as `snowroll` and exits 0. The lines of one
   page run in order in one scratch directory (a later line may read what an
   earlier one wrote), with `examples/` of the repository visible there.
3. With --python PY (an interpreter that imports the snowroll package), every
   ```python block of docs/guide/*.md runs with it and exits 0.

Only the standard library: this runs before and without the Python package.
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# One example may run a sweep of a few hundred points or 10^5 turns: seconds
# on the test build. A minute means it hangs.
TIMEOUT_S = 60

LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
FENCE = re.compile(r"^```(\w*)\s*$")


def markdown_files():
    files = [ROOT / "README.md", ROOT / "bench" / "README.md"]
    files += sorted((ROOT / "docs").rglob("*.md"))
    return [f for f in files if f.exists()]


def anchor(heading):
    """GitHub's anchor of a heading's text."""
    text = re.sub(r"[`*_]", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors_of(path):
    found = set()
    in_code = False
    for line in path.read_text(encoding="utf-8").splitlines():
        if FENCE.match(line):
            in_code = not in_code
        elif not in_code and line.startswith("#"):
            found.add(anchor(line.lstrip("#")))
    return found


def outside_code(text):
    """The text of a Markdown file without its fenced code blocks."""
    keep, in_code = [], False
    for line in text.splitlines():
        if FENCE.match(line):
            in_code = not in_code
        elif not in_code:
            keep.append(line)
    return "\n".join(keep)


def check_links():
    errors = []
    for md in markdown_files():
        for target in LINK.findall(outside_code(md.read_text(encoding="utf-8"))):
            if re.match(r"^[a-z]+:", target):
                continue  # http:, https:, mailto:
            path, _, fragment = target.partition("#")
            dest = (md.parent / path).resolve() if path else md
            where = f"{md.relative_to(ROOT)}: link {target}"
            try:
                dest.relative_to(ROOT)
            except ValueError:
                errors.append(f"{where} leaves the repository")
                continue
            if not dest.exists():
                errors.append(f"{where}: no such file")
            elif fragment and dest.suffix == ".md" and fragment not in anchors_of(dest):
                errors.append(f"{where}: no heading #{fragment} in {dest.relative_to(ROOT)}")
    return errors


def blocks(path, language):
    """The fenced blocks of `language` in a Markdown file, as lists of lines."""
    found, lang, current = [], None, None
    for line in path.read_text(encoding="utf-8").splitlines():
        fence = FENCE.match(line)
        if fence and current is None:
            lang, current = fence.group(1), []
        elif fence:
            if lang == language:
                found.append(current)
            current = None
        elif current is not None:
            current.append(line)
    return found


def run_examples(snowroll, python):
    errors, ran = [], 0
    for page in sorted((ROOT / "docs" / "guide").glob("*.md")):
        with tempfile.TemporaryDirectory() as scratch:
            scratch = Path(scratch)
            (scratch / "examples").symlink_to(ROOT / "examples")
            bin_dir = scratch / ".bin"
            bin_dir.mkdir()
            (bin_dir / "snowroll").symlink_to(Path(snowroll).resolve())
            env = dict(os.environ, PATH=f"{bin_dir}{os.pathsep}{os.environ['PATH']}")
            commands = [
                ("sh", line)
                for block in blocks(page, "sh")
                for line in block
                if line.startswith("snowroll ")
            ]
            if python:
                commands += [("python", "\n".join(b)) for b in blocks(page, "python")]
            for kind, code in commands:
                argv = ["bash", "-c", code] if kind == "sh" else [python, "-c", code]
                ran += 1
                try:
                    done = subprocess.run(
                        argv, cwd=scratch, env=env, capture_output=True, text=True,
                        timeout=TIMEOUT_S,
                    )
                except subprocess.TimeoutExpired:
                    errors.append(f"{page.name}: over {TIMEOUT_S} s: {code}")
                    continue
                if done.returncode != 0:
                    tail = (done.stderr or done.stdout).strip().splitlines()[-3:]
                    errors.append(
                        f"{page.name}: exit {done.returncode}: {code}\n    " + "\n    ".join(tail)
                    )
    return errors, ran


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("snowroll", help="the snowroll program the examples run")
    parser.add_argument("--python", help="an interpreter with the snowroll package")
    args = parser.parse_args()
    errors = check_links()
    example_errors, ran = run_examples(args.snowroll, args.python)
    errors += example_errors
    for e in errors:
        print(f"check-guide: {e}", file=sys.stderr)
    print(f"check-guide: {len(markdown_files())} Markdown files, {ran} examples, {len(errors)} problems")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
