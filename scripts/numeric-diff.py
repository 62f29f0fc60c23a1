#!/usr/bin/env python3
"""How far apart the numbers of two text outputs are, for changes that may move only the last bits.

usage: scripts/numeric-diff.py DIR_A DIR_B FILE [FILE ...]
       (FILE relative to both directories, e.g. the files `scripts/same-outputs.sh compare` lists)

Each file is read as text (CSV, JSON, Markdown, stdout): every number in it, in any notation (`1`, `-2.5`,
`3e-7`, `1.0E+3`), is replaced by a placeholder, and the text that remains must be the same in both files (a
changed word, column or row count is a difference this script reports as `TEXT`, not as a number). The hex dumps
of float64 arrays in same-outputs.sh's python-api.txt (`bytes 0000...`) are read as their numbers. The numbers
are then paired in order and their relative difference |a - b| / max(|a|, |b|) taken (0 when both are 0). It
prints, per file, the number of numbers that differ and the largest relative difference with its pair, then
the largest over all files; it exits 1 if any file's text differs or cannot be read as text."""
import re
import struct
import sys

NUMBER = re.compile(r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?')


HEX_FLOATS = re.compile(r'\bbytes ([0-9a-f]+)\b')


def decode_hex_floats(m):
    """`bytes HEX` (the Python snippet's dump of a float64 array, little-endian) as its numbers."""
    raw = m.group(1)
    if len(raw) % 16:
        return m.group(0)
    values = struct.unpack(f'<{len(raw) // 16}d', bytes.fromhex(raw))
    return 'bytes<' + ' '.join(repr(v) for v in values) + '>'


def split(text):
    """The text with each number replaced by a placeholder, and the numbers in order."""
    text = HEX_FLOATS.sub(decode_hex_floats, text)
    numbers = [m.group(0) for m in NUMBER.finditer(text)]
    return NUMBER.sub('#', text), numbers


def relative(a, b):
    if a == b:
        return 0.0
    return abs(a - b) / max(abs(a), abs(b))


def main(argv):
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    dir_a, dir_b, files = argv[1], argv[2], argv[3:]
    worst, worst_file, bad = 0.0, None, False
    for name in files:
        try:
            text_a = open(f'{dir_a}/{name}', encoding='utf-8').read()
            text_b = open(f'{dir_b}/{name}', encoding='utf-8').read()
        except (OSError, UnicodeDecodeError) as e:
            print(f'{name}: UNREADABLE ({e})')
            bad = True
            continue
        skel_a, nums_a = split(text_a)
        skel_b, nums_b = split(text_b)
        if skel_a != skel_b or len(nums_a) != len(nums_b):
            print(f'{name}: TEXT differs (not only numbers)')
            bad = True
            continue
        file_worst, pair, changed = 0.0, None, 0
        for a, b in zip(nums_a, nums_b):
            if a == b:
                continue
            changed += 1
            r = relative(float(a), float(b))
            if r >= file_worst:
                file_worst, pair = r, (a, b)
        print(f'{name}: {changed} of {len(nums_a)} numbers differ, max relative {file_worst:.3e}'
              + (f' ({pair[0]} vs {pair[1]})' if pair else ''))
        if file_worst >= worst:
            worst, worst_file = file_worst, name
    print(f'largest relative difference: {worst:.3e}' + (f' in {worst_file}' if worst_file else ''))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
