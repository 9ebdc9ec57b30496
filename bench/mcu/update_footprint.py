#!/usr/bin/env python3
"""Rewrites the numbers of docs/footprint.md's table (and its goal rows) from run.sh output,
its table of the largest functions of `full` on thumbv6m from the firmware run.sh built, and
its table of `full`'s flash by library function (flash.py, which builds it with line tables).

    bench/mcu/run.sh > results.txt; BOARD=microbit bench/mcu/run.sh >> results.txt
    python3 bench/mcu/update_footprint.py results.txt
"""
import re
import sys
from pathlib import Path

rows = {}
for line in Path(sys.argv[1]).read_text().splitlines():
    m = re.match(r"preset=(\S+) target=(\S+) lib_flash=(\d+) static_ram=(\d+) stack=(\d+) instructions_per_frame=(\d+)", line)
    if m:
        rows[(m.group(1), m.group(2))] = [int(m.group(i)) for i in range(3, 7)]

doc = Path(__file__).resolve().parent.parent.parent / "docs" / "footprint.md"
triples = {"thumbv6m": "thumbv6m-none-eabi", "thumbv7em": "thumbv7em-none-eabihf"}
out = []
for line in doc.read_text().split("\n"):
    m = re.match(r"^\| `(\w+)` \|(.*)\| (thumbv6m|thumbv7em) \| [\d,]+ \| [\d,]+ \| [\d,]+ \| [\d,]+ \|$", line)
    if m:
        preset, desc, short = m.groups()
        key = (preset, "thumbv6m-none-eabi@microbit" if "micro:bit" in desc else triples[short])
        if key in rows:
            v = rows[key]
            line = f"| `{preset}` |{desc}| {short} | {v[0]:,} | {v[1]:,} | {v[2]:,} | {v[3]:,} |"
    m = re.match(r"^\| thumbv6m library flash, `(\w+)` at most (\d+) KiB \| [\d,]+ B \| (.*) \|$", line)
    if m and (m.group(1), "thumbv6m-none-eabi") in rows:
        flash = rows[(m.group(1), "thumbv6m-none-eabi")][0]
        status = "reached" if flash <= int(m.group(2)) * 1024 else "not reached"
        line = f"| thumbv6m library flash, `{m.group(1)}` at most {m.group(2)} KiB | {flash:,} B | {status} |"
    m = re.match(r"^\| `full` instructions per frame on (thumbv6m|thumbv7em) at most ([\d.]+) M \| .* \| .* \|$", line)
    if m and ("full", triples[m.group(1)]) in rows:
        n = rows[("full", triples[m.group(1)])][3]
        status = "reached" if n <= float(m.group(2)) * 1e6 else "not reached"
        line = f"| `full` instructions per frame on {m.group(1)} at most {m.group(2)} M | {n:,} | {status} |"
    m = re.match(r"^\| `bands` at most 1.25x `full` on (thumbv6m|thumbv7em) \| .* \| .* \|$", line)
    if m and ("bands", triples[m.group(1)]) in rows and ("full", triples[m.group(1)]) in rows:
        ratio = rows[("bands", triples[m.group(1)])][3] / rows[("full", triples[m.group(1)])][3]
        status = "reached" if ratio <= 1.25 else "not reached"
        line = f"| `bands` at most 1.25x `full` on {m.group(1)} | {ratio:.2f}x | {status} |"
    m = re.match(r"^\| `(gouraud|textured)` at most 2x `full` on (thumbv6m|thumbv7em) \| .* \| .* \|$", line)
    if m and (m.group(1), triples[m.group(2)]) in rows and ("full", triples[m.group(2)]) in rows:
        ratio = rows[(m.group(1), triples[m.group(2)])][3] / rows[("full", triples[m.group(2)])][3]
        status = "reached" if ratio <= 2 else "not reached"
        # Three decimals: a ratio just under its goal reads as under it.
        line = f"| `{m.group(1)}` at most 2x `full` on {m.group(2)} | {ratio:.3f}x | {status} |"
    out.append(line)
text = "\n".join(out)

# The largest functions of `full` on thumbv6m (the ELF run.sh left), between the markers.
elf = Path(__file__).resolve().parent / "target" / "mps2" / "thumbv6m-none-eabi" / "release-s" / "full"
start, end = "<!-- symbols -->", "<!-- /symbols -->"
if elf.exists() and start in text and end in text:
    import subprocess
    nm = subprocess.run(["nm", "--size-sort", "-S", "-C", str(elf)], capture_output=True, text=True).stdout
    syms = []
    for l in nm.splitlines():
        parts = l.split(" ", 3)
        if len(parts) == 4 and parts[2] in "tTrR":
            syms.append((int(parts[1], 16), parts[3]))
    syms.sort(reverse=True)
    table = ["| bytes | function (harness: `mcu_bench`; the library's code inlined into it counts there) |", "|---:|---|"]
    for size, name in syms[:15]:
        table.append(f"| {size:,} | `{name}` |")
    i, j = text.index(start) + len(start), text.index(end)
    text = text[:i] + "\n" + "\n".join(table) + "\n" + text[j:]
elif start in text:
    print(f"no {elf}: the symbol table is left as it was (run bench/mcu/run.sh first)")

# Where the library's flash in `full` on thumbv6m goes, by source function (flash.py).
start, end = "<!-- sources -->", "<!-- /sources -->"
if start in text and end in text:
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from flash import table as flash_table

    i, j = text.index(start) + len(start), text.index(end)
    text = text[:i] + "\n" + flash_table("full", "thumbv6m-none-eabi", 15) + "\n" + text[j:]
doc.write_text(text)
print(f"updated {doc} from {len(rows)} results")
