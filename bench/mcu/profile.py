#!/usr/bin/env python3
"""Where a firmware preset's instructions go on an emulated Cortex-M core.

    python3 bench/mcu/profile.py [PRESET] [TARGET] [LINES]
    (defaults: full thumbv6m-none-eabi 40)

Builds the preset with line tables (the same code: debug information changes no instruction),
runs it under QEMU logging every translated block and every block executed, and prints, per
drawn frame: instructions by function, the library calls (64-bit multiply and division, bit
counting, shifts) by the source line that makes them, and the busiest source lines. What the
firmware executes from the first drawn frame on is traced, the harness's work between frames
too (clears, hashing): functions of the harness are marked, and code the compiler inlined into
them counts as theirs. Start-up (calibration, building the mesh) is left out.
The log is large (about 1.5 GB for `full` on the M0) and is deleted afterwards.

With ASM=<part of a function name> it also prints that function's disassembly (llvm-objdump),
each instruction with the times it ran per frame: the place to read a hot loop.
With AGAINST=<preset> it profiles both presets on the core and prints what the first runs
beyond the second, by function and by source line (the harness's code left out): where a
preset's cost over its base goes, as the `ratio` goals weigh it.
"""

import bisect
import collections
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
# Frames the firmware draws: FRAMES measured ones and one more for the stack measurement.
FRAMES_DRAWN = 5
# Harness functions (whole symbols), marked in the profile.
HARNESS = ("mcu_bench::run_each", "mcu_bench::spin", "mcu_bench::Meter", "mcu_bench::stack",
           "torus_mesh", "__aeabi_memset", "__aeabi_memclr", "memset", "Reset", "frame_hash")
LIBRARY = re.compile(r"^(__aeabi_|__clz|__udiv|__div|__mul|compiler_builtins)|div_rem")


def machine(target):
    return "mps2-an385" if target.startswith("thumbv6m") else "mps2-an386"


def build(preset, target, target_dir):
    env = dict(os.environ, CARGO_PROFILE_RELEASE_S_DEBUG="line-tables-only")
    # The presets that need features of their own (as run.sh builds them).
    features = {"knobs": ["--features", "micromath"], "phong": ["--features", "phong"],
                "variants": ["--features", "wireframe"]}.get(preset, [])
    subprocess.run(["cargo", "build", "--quiet", "--profile", "release-s", "--target", target,
                    "--target-dir", target_dir, "--bin", preset] + features,
                   cwd=HERE, env=env, check=True)
    return os.path.join(target_dir, target, "release-s", preset)


def trace(binary, target, log):
    out = subprocess.run(["qemu-system-arm", "-M", machine(target), "-nographic",
                          "-semihosting-config", "enable=on,target=native", "-icount", "shift=10",
                          "-d", "in_asm,exec,nochain", "-D", log, "-kernel", binary],
                         stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=900)
    return out.stdout.strip().splitlines()[-1:] if out.stdout else []


def executed(log, is_call, start):
    """Instructions executed per address from the first run of the block at `start` on, and
    library calls counted by calling block: a block of a library routine entered from a block
    that `is_call(previous, pc)` accepts.

    A block's address may have more than one translation at once, of different lengths: under
    `-icount` QEMU also translates blocks cut short to the instructions left in the budget, and
    keeps them beside the whole ones. A translation is told apart by its address and its
    compile flags (which hold the cut's length), as each run's trace line gives them; a run is
    counted against the translation of both."""
    blocks, current, addrs = {}, None, []
    runs = collections.Counter()
    calls = collections.Counter()
    previous = None
    with open(log, "rb") as f:
        for line in f:
            if line.startswith(b"IN:"):
                current, addrs = None, []
            elif line.startswith(b"0x") and b":  " in line:
                a = int(line[:10], 16)
                if current is None:
                    current = a
                addrs.append(a)
            elif line.startswith(b"Trace"):
                # "Trace 0: <host code> [cs_base/pc/flags/cflags] symbol"
                fields = line.split(b"[", 1)[1].split(b"]", 1)[0].split(b"/")
                pc = int(fields[1], 16)
                key = (pc, fields[3])
                if current is not None:
                    # The block just translated is the one this line runs.
                    if current == pc:
                        blocks[key] = addrs
                    current = None
                if start is not None:
                    if pc != start:
                        continue
                    start = None
                runs[key] += 1
                if previous is not None and is_call(previous, pc):
                    calls[(pc, previous)] += 1
                previous = pc
    count = collections.Counter()
    for key, n in runs.items():
        for a in blocks.get(key, ()):
            count[a] += n
    return count, calls


def code_symbols(binary):
    """(start, end, name) of every code symbol, by address (mapping symbols, `$t` and the
    like, left out)."""
    out = subprocess.run(["nm", "-S", "-C", "-n", binary], capture_output=True, text=True).stdout
    found = []
    for line in out.splitlines():
        parts = line.split(" ", 3)
        if len(parts) == 4 and parts[2] in "tT" and not parts[3].startswith("$"):
            start = int(parts[0], 16) & ~1
            found.append((start, start + int(parts[1], 16), parts[3]))
    return found


def symbols(binary):
    """The function holding an address, and the address of the harness's frame function."""
    table = [(start, name) for start, _, name in code_symbols(binary)]
    starts = [s for s, _ in table]

    def of(address):
        i = bisect.bisect_right(starts, address) - 1
        return table[i][1] if i >= 0 else "?"
    frame = next((a for a, name in table if name.startswith("mcu_bench::frame")), None)
    return of, frame


def chains(binary, addresses, functions=False):
    """addr2line's inlining chain of each address, innermost first: its source lines, or with
    `functions` each frame's function name followed by its line."""
    flags = ["-a", "-i"] + (["-f", "-C"] if functions else [])
    out = subprocess.run(["addr2line"] + flags + ["-e", binary] + [hex(a) for a in addresses],
                         capture_output=True, text=True).stdout
    found, current = {}, None
    for line in out.splitlines():
        if line.startswith("0x"):
            current = int(line, 16)
            found[current] = []
        elif current is not None:
            found[current].append(line)
    return found


def lines(binary, addresses):
    """The source line of each address: the innermost one in this repository's code (inlined
    library code counts where the crate's code used it), else the innermost one."""
    short = lambda l: "/".join(l.split(" (")[0].split("/")[-3:])
    ours = lambda l: "/rustc/" not in l and "/.cargo/" not in l and "??" not in l
    found = {}
    for address, chain in chains(binary, addresses).items():
        mine = [l for l in chain if ours(l)]
        found[address] = short((mine or chain or ["?"])[0])
    return found


def profile(preset, target):
    """Runs `preset` on `target` under the trace: its result line, instructions per address,
    each address's function and source line, the library calls by callee and calling line,
    and the binary (all counts over every drawn frame)."""
    binary = build(preset, target, os.path.join(HERE, "target", "profile"))
    symbol, frame = symbols(binary)
    names = {}

    def name_of(pc):
        if pc not in names:
            names[pc] = symbol(pc)
        return names[pc]

    library = lambda pc: LIBRARY.search(name_of(pc)) is not None

    def is_call(previous, pc):
        return library(pc) and not library(previous) and not harness(name_of(previous))

    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "qemu.log")
        result = trace(binary, target, log)
        count, raw_calls = executed(log, is_call, frame)
    where = lines(binary, sorted(count))
    caller_line = lines(binary, sorted({p for _, p in raw_calls}))
    calls = collections.Counter()
    for (pc, previous), n in raw_calls.items():
        calls[(name_of(pc), caller_line.get(previous, "?"))] += n
    by_function = collections.Counter()
    by_line = collections.Counter()
    library_lines = collections.Counter()
    for a, n in count.items():
        name = name_of(a)
        by_function[name] += n
        by_line[where[a]] += n
        # The bench's own code (the display stand-ins' hashing, inlined into functions of
        # other names) is no library line either.
        if not harness(name) and not where[a].startswith("mcu/"):
            library_lines[where[a]] += n
    return {"result": result, "count": count, "where": where, "calls": calls, "binary": binary,
            "by_function": by_function, "by_line": by_line, "library_lines": library_lines}


def harness(name):
    return any(h in name for h in HARNESS)


def per(n):
    return n / FRAMES_DRAWN


def report(preset, target, top):
    p = profile(preset, target)
    count = p["count"]
    print(f"{preset} on {target} ({machine(target)}): {' '.join(p['result'])}")
    print(f"traced instructions per drawn frame, harness included: {per(sum(count.values())):,.0f}\n")
    print("by function:")
    for name, n in p["by_function"].most_common(top):
        mark = "  (harness)" if harness(name) else ""
        print(f"  {per(n):>11,.0f}  {name[:100]}{mark}")
    print("\nlibrary calls per frame, by the line that makes them (first block of a call):")
    for (name, line), n in p["calls"].most_common(top):
        print(f"  {per(n):>8,.0f}  {name[:40]:40}  {line}")
    print("\nbusiest source lines (inlined code counts where it was written):")
    for line, n in p["by_line"].most_common(top):
        print(f"  {per(n):>11,.0f}  {line}")
    if os.environ.get("ASM"):
        disassembly(p["binary"], os.environ["ASM"], lambda a: per(count.get(a, 0)), p["where"])


def compare(preset, base, target, top):
    """What `preset` runs beyond `base` on one core, per frame: by function and by source line,
    the harness's code left out, the largest differences either way first."""
    ours, theirs = profile(preset, target), profile(base, target)
    for p, name in ((ours, preset), (theirs, base)):
        print(f"{name} on {target}: {' '.join(p['result'])}")

    def table(title, key):
        a, b = ours[key], theirs[key]
        rows = [(per(a[k] - b[k]), per(a[k]), per(b[k]), k) for k in set(a) | set(b)
                if not (key == "by_function" and harness(k))]
        rows.sort(key=lambda r: -abs(r[0]))
        print(f"\n{title}: {preset} less {base}, {preset}, {base}")
        print(f"  {sum(r[0] for r in rows):>+11,.0f}  (all of them)")
        for d, x, y, k in rows[:top]:
            print(f"  {d:>+11,.0f}  {x:>11,.0f}  {y:>11,.0f}  {k[:100]}")
    table("by function", "by_function")
    table("by source line (the harness's code left out)", "library_lines")


def main():
    preset = sys.argv[1] if len(sys.argv) > 1 else "full"
    target = sys.argv[2] if len(sys.argv) > 2 else "thumbv6m-none-eabi"
    top = int(sys.argv[3]) if len(sys.argv) > 3 else 40
    if os.environ.get("AGAINST"):
        compare(preset, os.environ["AGAINST"], target, top)
    else:
        report(preset, target, top)


def disassembly(binary, part, runs, where):
    """The functions whose names contain `part`, instruction by instruction with their runs
    per frame and source lines."""
    out = subprocess.run(["llvm-objdump", "-d", "-C", "--no-show-raw-insn", binary],
                         capture_output=True, text=True).stdout
    inside = False
    for line in out.splitlines():
        head = re.match(r"^([0-9a-f]+) <(.*)>:$", line)
        if head:
            # Mapping symbols ($t, $d: code and literal pools) split a function's listing;
            # they continue the function they lie in.
            if head.group(2).startswith("$"):
                continue
            inside = part in head.group(2)
            if inside:
                print(f"\n{head.group(2)}")
            continue
        code = re.match(r"^\s*([0-9a-f]+):\s*(.*)$", line)
        if inside and code:
            a = int(code.group(1), 16)
            print(f"  {runs(a):>9,.0f}  {a:08x}  {code.group(2)[:48]:48}  {where.get(a, '')}")


if __name__ == "__main__":
    main()
