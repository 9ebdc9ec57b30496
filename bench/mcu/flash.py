#!/usr/bin/env python3
"""Where a firmware preset's flash goes, by the library function its code came from.

    python3 bench/mcu/flash.py [PRESET] [TARGET] [LINES]
    (defaults: full thumbv6m-none-eabi 15)

With fat LTO nearly all of the library is inlined into a few large functions of the harness,
so that a symbol table says little of it. This builds the preset with line tables (the same
code, as profile.py does), reads the function each halfword of its code was inlined from
(addr2line), and counts every byte of the crate's code once, in the outermost function of the
crate it lies in: the entry points a firmware calls (`prepare`, `draw`, `view`, ...) and the
functions the compiler kept out of line. Bytes of the harness, `core` and the compiler's
routines are not counted. Prints a Markdown table, largest first.
"""

import collections
import os
import re
import subprocess
import sys

from profile import HERE, build, chains, code_symbols

# The crate's own source files, as the line tables name them.
SOURCE = os.path.join(os.path.dirname(os.path.dirname(HERE)), "src") + os.sep


def short(name):
    """A function's name without generic arguments or path."""
    while True:
        shorter = re.sub(r"<[^<>]*>", "", name)
        if shorter == name:
            break
        name = shorter
    return re.sub(r"::h[0-9a-f]{16}$", "", name).split("::")[-1]


def crate_function(frames, symbol):
    """The outermost of `frames` (innermost first: (function, location)) in the crate's
    sources, as (name, file); the name of the `symbol` holding it where the line tables name
    none (binutils' addr2line then gives a mapping symbol)."""
    mine = [(f, where) for f, where in frames if where.startswith(SOURCE)]
    if not mine:
        return None
    name, where = mine[-1]
    if name.startswith("$") or name == "??":
        name = symbol
    return short(name), where[len(SOURCE):].split(":")[0]


def bytes_by_function(binary):
    halfwords = [(a, name) for start, end, name in code_symbols(binary) for a in range(start, end, 2)]
    symbol_of = dict(halfwords)
    counts = collections.Counter()
    for address, frames in chains(binary, [a for a, _ in halfwords], functions=True).items():
        found = crate_function(list(zip(frames[0::2], frames[1::2])), symbol_of[address])
        if found:
            counts[found] += 2
    return counts


def table(preset, target, lines):
    binary = build(preset, target, os.path.join(HERE, "target", "profile"))
    counts = bytes_by_function(binary)
    rows = ["| bytes | library function (its own code and all inlined into it) |", "|---:|---|"]
    rows += [f"| {n:,} | `{name}` ({path}) |" for (name, path), n in counts.most_common(lines)]
    rows.append(f"| {sum(counts.values()):,} | all of the crate's code |")
    return "\n".join(rows)


if __name__ == "__main__":
    preset = sys.argv[1] if len(sys.argv) > 1 else "full"
    target = sys.argv[2] if len(sys.argv) > 2 else "thumbv6m-none-eabi"
    lines = int(sys.argv[3]) if len(sys.argv) > 3 else 15
    print(table(preset, target, lines))
