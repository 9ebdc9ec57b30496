#!/usr/bin/env python3
"""Where the `full` preset's instructions go on the emulated Cortex-M4F and Cortex-M0, stage by
stage, measured exactly: the frame is cut short after each stage in turn (a copy of the crate
with one early return, behind `core::hint::black_box` so that nothing before it is optimised
away) and `run.sh` counts the instructions per frame of each cut; a stage's cost is the
difference between consecutive cuts. The working tree is never touched: the crate is copied to a
temporary directory first. Each cut changes the code around it a little (inlining, registers),
so a stage's figure is good to a few per cent of the frame; a stage smaller than that error
(its difference negative on a core) is reported together with the next one.

    python3 bench/mcu/stages.py            # prints a Markdown table (about a minute)
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TARGETS = ["thumbv7em-none-eabihf", "thumbv6m-none-eabi"]
BB = "core::hint::black_box"

# (stage measured by this cut, what the frame still does, [(file, anchor, replacement)]),
# from the whole frame down to the vertex stage alone. Each anchor must occur in the source
# (the script stops otherwise: update it with the code).
CUTS = [
    ("pixels (depth test and writes)", "everything", []),
    ("span entry (bounds check, depth start)", "no pixel loops", [(
        "src/target/depth.rs",
        "    let (mut acc, st) = (acc as u32, st as u32);\n"
        "    for (d, c) in depths.iter_mut().zip(colors.iter_mut()) {",
        "    let (mut acc, st) = (acc as u32, st as u32);\n"
        f"    if {BB}(true) {{ let _ = (&mut next_color, st, acc, depths.len(), colors.len()); "
        f"return {BB}(failed); }}\n"
        "    for (d, c) in depths.iter_mut().zip(colors.iter_mut()) {",
    ), (
        # The `asm` feature's Thumb-2 loop (the M4F's presets have it).
        "src/target/thumb2.rs",
        "    let d = depths.as_mut_ptr().wrapping_add(n);",
        f"    if {BB}(true) {{ let _ = (st, acc, bits); return {BB}(failed); }}\n"
        "    let d = depths.as_mut_ptr().wrapping_add(n);",
    ), (
        # The same feature's row loop: each span entered, no pixel loop.
        "src/target/thumb2.rs",
        '            $pixels!("3", ["r4", "r5", "r0", "r3", "r2", "r1"], $it, $pass, [$($count)?]),',
        '            "b 4f",\n'
        '            $pixels!("3", ["r4", "r5", "r0", "r3", "r2", "r1"], $it, $pass, [$($count)?]),',
    ), (
        # The M0's row loop in Thumb-1.
        "src/target/thumb1.rs",
        '                "3:",\n                "lsrs r0, r2, #15",',
        '                "b 4f",\n                "3:",\n                "lsrs r0, r2, #15",',
    )]),
    ("rows (edge stepping, clipping, depth walk)", "no spans", [(
        "src/target/surface.rs",
        "failed = test_span(ds, cs, depth.at(x0), g, failed);",
        f"failed = {BB}((ds.len(), cs.len(), depth.at(x0), failed)).3;"
        " let _ = (&mut test_span, g);",
    ), (
        "src/target/thumb2.rs",
        '            "bge 4f",',
        '            "b 4f",',
    ), (
        "src/target/thumb1.rs",
        '                "bhs 22f",',
        '                "b 4f",',
    )]),
    ("fill set-up (colour, depth walk: steps and start; first row)", "no rows", [(
        "src/target/surface.rs",
        "        let (mut y, width) = (spans.row(), self.color.width() as usize);",
        f"        if {BB}(true) {{ {BB}((&spans, &depth)); return; }}\n"
        "        let (mut y, width) = (spans.row(), self.color.width() as usize);",
    ), (
        # The `asm` feature's row loops (both cores): everything up to the call.
        "src/target/asm_rows.rs",
        "    unsafe { core_rows::rows::<T, K>(block, clamp) };",
        f"    if {BB}(true) {{ {BB}((&*block, colors.len(), depths.len())); return; }}\n"
        "    unsafe { core_rows::rows::<T, K>(block, clamp) };",
    )]),
    ("span set-up (sorting, edge steppers)", "no fill set-up", [(
        # The rows and edges as the build sets them up (for the `asm` row loops as runs: on both
        # cores in assembly, from the corners), then nothing of the colour or the depth walk.
        "src/target/surface.rs",
        "        match paint.solid() {\n            Some(rgb) if Q::UNIFORM => {",
        f"        if {BB}(true) {{\n"
        "            #[cfg(all(feature = \"asm\", fixed3d_thumb))]\n"
        "            #[allow(unsafe_code)]\n"
        "            {\n"
        "                #[cfg(fixed3d_thumb1)]\n"
        "                use super::thumb1 as core_rows;\n"
        "                #[cfg(fixed3d_thumb2)]\n"
        "                use super::thumb2 as core_rows;\n"
        "                let mut block = core::mem::MaybeUninit::<super::asm_rows::RowBlock>::uninit();\n"
        "                let (p, area) = (&triangle.p, triangle.area);\n"
        "                let rows = (self.clip.y0, self.clip.y1);\n"
        "                let out = block.as_mut_ptr();\n"
        f"                {BB}(unsafe {{ core_rows::triangle_runs(p, area, rows, out) }});\n"
        f"                {BB}(&block);\n"
        "            }\n"
        "            #[cfg(not(all(feature = \"asm\", fixed3d_thumb)))]\n"
        "            if let Some(rows) = rows_in_range(triangle.p, self.clip, triangle.area) {\n"
        "                #[cfg(all(feature = \"asm\", fixed3d_asm_rows))]\n"
        f"                {BB}(rows.runs());\n"
        "                #[cfg(not(all(feature = \"asm\", fixed3d_asm_rows)))]\n"
        f"                {BB}(rows.spans((self.clip.x0, self.clip.x1), u32::MAX));\n"
        f"            }}\n            {BB}(paint);\n            return Ok(());\n        }}\n"
        "        match paint.solid() {\n            Some(rgb) if Q::UNIFORM => {",
    )]),
    ("flat shading (Lambert from the kept face normal)", "no spans or depth walk", [(
        "src/pipeline/draw.rs",
        "    bump(&mut stats.drawn);\n",
        f"    bump(&mut stats.drawn);\n    if {BB}(true) {{ {BB}((&p, &z, area, paint)); "
        "return Ok(()); }\n",
    )]),
    ("a drawn triangle's inputs", "no shading", [(
        "src/pipeline/draw.rs",
        "        // Gouraud needs per-vertex normals;",
        f"        if {BB}(true) {{ {BB}(&face); return Ok(()); }}\n"
        "        // Gouraud needs per-vertex normals;",
    )]),
    ("triangle walk (fetch, trivial reject, culling)", "vertex stage and walk", [(
        "src/pipeline/draw.rs",
        "        let p = map3(*v, |v| v.0);\n        // Culling came first",
        f"        if {BB}(true) {{ return Ok(()); }}\n"
        "        let p = map3(*v, |v| v.0);\n        // Culling came first",
    )]),
    ("vertex stage (and the frame's camera and model matrix)", "vertex stage", [(
        "src/pipeline/draw.rs",
        "        let mut stats = Stats::default();\n        let map = ScreenMap::new(",
        f"        let mut stats = Stats::default();\n        if {BB}(true) {{ return Ok(stats); }}\n"
        "        let map = ScreenMap::new(",
    )]),
]


def count(crate):
    """Instructions per frame of `full` on each target, for the crate copy at `crate`."""
    env = dict(os.environ, PRESETS="full", TARGETS=" ".join(TARGETS),
               CARGO_TARGET_DIR=os.path.join(HERE, "target", "stages"),
               RESULTS=os.path.join(crate, "results.tsv"))
    out = subprocess.run(["bash", os.path.join(crate, "bench/mcu/run.sh")], env=env,
                         capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"run.sh failed:\n{out.stdout}\n{out.stderr}")
    found = {}
    for line in out.stdout.splitlines():
        t = re.search(r"target=(\S+)", line)
        n = re.search(r"instructions_per_frame=(\d+)", line)
        if t and n:
            found[t.group(1)] = int(n.group(1))
    return found


def main():
    files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                           check=True).stdout.split()
    with tempfile.TemporaryDirectory() as tmp:
        crate = os.path.join(tmp, "main")
        for f in files:
            os.makedirs(os.path.dirname(os.path.join(crate, f)), exist_ok=True)
            # A plain copy, stamped now: the copy's paths are the checkout's relative ones
            # (the firmware is a member of the crate's workspace), so Cargo would take sources
            # keeping the checkout's older times for the last run's cut, already built.
            shutil.copyfile(os.path.join(ROOT, f), os.path.join(crate, f))
        totals = []
        for stage, left, patches in CUTS:
            for path, anchor, replacement in patches:
                p = os.path.join(crate, path)
                with open(p) as fh:
                    text = fh.read()
                if anchor not in text:
                    sys.exit(f"stages.py: anchor not found in {path}: {anchor!r}")
                with open(p, "w") as fh:
                    fh.write(text.replace(anchor, replacement, 1))
            totals.append((stage, left, count(crate)))
            print(f"  {left}: {totals[-1][2]}", file=sys.stderr)
    whole = totals[0][2]
    for t in TARGETS:
        if any(cut.get(t, 0) >= whole.get(t, 0) for _, _, cut in totals[1:]):
            sys.exit(f"stages.py: on {t} a cut counts no fewer instructions than the whole "
                     f"frame ({[c.get(t) for _, _, c in totals]}): a stale build?")
    print("| stage | Cortex-M4F | share | Cortex-M0 | share |")
    print("|---|---:|---:|---:|---:|")
    nothing = {t: 0 for t in TARGETS}
    i = 0
    while i < len(totals):
        stage, _, here = totals[i]
        # A stage so small that cutting it moved the code around it by more than it costs
        # would come out negative: it is reported together with the next one.
        j = i + 1
        while j < len(totals) and any(here.get(t, 0) < totals[j][2].get(t, 0) for t in TARGETS):
            stage += "; " + totals[j][0]
            j += 1
        after = totals[j][2] if j < len(totals) else nothing
        cells = []
        for t in TARGETS:
            v = here.get(t, 0) - after.get(t, 0)
            cells += [f"{v:,}", f"{100 * v / max(whole.get(t, 1), 1):.1f}%"]
        print(f"| {stage} | " + " | ".join(cells) + " |")
        i = j
    print("| whole frame | " + " | ".join(
        [f"{whole.get(t, 0):,} | 100%" for t in TARGETS]) + " |")


if __name__ == "__main__":
    main()
