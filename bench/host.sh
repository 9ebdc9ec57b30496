#!/usr/bin/env bash
# Instructions per frame of the reference scene on this host, counted by callgrind (exact and
# repeatable, unlike wall time): draw_scene (vertex stage, culling, shading, rasterising; clears
# excluded) per frame and per covered pixel, where they go by stage, and the median host time
# beside the crate's f64 reference renderer measured in the same run.
#   bench/host.sh [FRAMES]                 (default 20)
#   bench/host.sh --doc [FRAMES]           also rewrites docs/performance.md
#   HOST_GOAL=N bench/host.sh [FRAMES]     fails above N instructions per frame
set -euo pipefail
cd "$(dirname "$0")/.."
doc=0
if [[ "${1:-}" == --doc ]]; then doc=1; shift; fi
frames=${1:-20}
if ! command -v valgrind >/dev/null; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo=sudo
    $sudo apt-get update -qq && $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq valgrind >/dev/null
fi
# The headline count from a build made as the firmware is (one codegen unit, fat LTO: the
# `bench-lto` profile); the stage breakdown from the default release build, whose function
# boundaries the breakdown needs (fat LTO inlines most of them), with `FIXED3D_STAGES` set
# (build.rs: the span set-up kept out of line, which the crate otherwise has in line).
# First the same frame into a target that counts fragments and writes (the example's
# TORUS_BENCH_COUNTED, a constant: see examples/torus_bench.rs), for what the counts cost.
# Every build has the `asm` feature, as the firmware presets do (on x86-64 the row loop in
# assembly, src/target/x86_64.rs); the headline's build is measured without it too. The mesh
# keeps its face normals (`FlatKept`), as the `full` firmware preset's does; the headline's
# build is measured with each face's normal found every frame too (`Flat`, the example's
# TORUS_BENCH_PER_FRAME_NORMALS).
cargo build --profile bench-lto --example torus_bench
cp target/bench-lto/examples/torus_bench target/bench-lto/examples/torus_bench_no_asm
TORUS_BENCH_PER_FRAME_NORMALS=1 cargo build --profile bench-lto --features asm --example torus_bench
cp target/bench-lto/examples/torus_bench target/bench-lto/examples/torus_bench_per_frame
TORUS_BENCH_COUNTED=1 cargo build --profile bench-lto --features asm --example torus_bench
cp target/bench-lto/examples/torus_bench target/bench-lto/examples/torus_bench_counted
FIXED3D_STAGES=1 cargo build --release --features asm --example torus_bench
cargo build --profile bench-lto --features asm --example torus_bench
no_asm_out=target/callgrind.torus-no-asm
NO_REFERENCE=1 valgrind --tool=callgrind --callgrind-out-file="$no_asm_out" target/bench-lto/examples/torus_bench_no_asm "$frames" >/dev/null 2>&1
per_frame_out=target/callgrind.torus-per-frame
NO_REFERENCE=1 valgrind --tool=callgrind --callgrind-out-file="$per_frame_out" target/bench-lto/examples/torus_bench_per_frame "$frames" >/dev/null 2>&1
counted_out=target/callgrind.torus-counted
counted_line=$(NO_REFERENCE=1 valgrind --tool=callgrind --callgrind-out-file="$counted_out" target/bench-lto/examples/torus_bench_counted "$frames" 2>/dev/null)
lto_out=target/callgrind.torus-lto
line=$(NO_REFERENCE=1 valgrind --tool=callgrind --callgrind-out-file="$lto_out" target/bench-lto/examples/torus_bench "$frames" 2>/dev/null)
out=target/callgrind.torus
NO_REFERENCE=1 valgrind --tool=callgrind --callgrind-out-file="$out" target/release/examples/torus_bench "$frames" >/dev/null 2>&1
covered=$(sed -E 's/.*covered ([0-9]+) pixels.*/\1/' <<<"$line")
ir() { # inclusive instructions of the first function whose name ends with $2, in profile $1
    callgrind_annotate --inclusive=yes "$1" 2>/dev/null |
        awk -v f="$2" '{ name = $0; sub(/ \[.*$/, "", name) } name ~ (f "$") { gsub(",", "", $1); print $1; exit }'
}
headline=$(ir "$lto_out" "torus_bench::draw_scene"); clear=$(ir "$lto_out" "torus_bench::clear_buffers")
counted=$(ir "$counted_out" "torus_bench::draw_scene")
no_asm=$(ir "$no_asm_out" "torus_bench::draw_scene")
per_frame=$(ir "$per_frame_out" "torus_bench::draw_scene")
draw=$(ir "$out" "torus_bench::draw_scene")
prepare=$(ir "$out" "pipeline::Frame::prepare"); walk=$(ir "$out" "Prepared<_,S>>::draw"); face=$(ir "$out" "Prepared<_,S>>::fill_face")
rows=$(ir "$out" "raster::triangle::rows_in_range"); runs=$(ir "$out" "raster::triangle::TriangleRows::runs")
shading=$(ir "$out" "Shading>::paint")
timing=$(target/bench-lto/examples/torus_bench 200)
report=$(awk -v h="$headline" -v d="$draw" -v c="$clear" -v n="$frames" -v px="$covered" -v pr="${prepare:-0}" -v wk="${walk:-0}" \
    -v fc="${face:-0}" -v sp="$(( ${rows:-0} + ${runs:-0} ))" -v sh="${shading:-0}" -v ct="$counted" -v na="$no_asm" -v pf="$per_frame" 'BEGIN {
    f = 1 / n;
    printf "draw_scene: %.3f M instructions per frame, %.1f per covered pixel (clear_buffers: %.3f M)\n\n", h*f/1e6, h*f/px, c*f/1e6;
    printf "Without the \x60asm\x60 feature (the loops compiled from Rust): %.3f M (%+.1f%%)\n\n", na*f/1e6, 100*(na-h)/h;
    printf "With each face\x27s normal found from its positions every frame (\x60Flat\x60, the mesh keeping\nnone, instead of \x60FlatKept\x60): %.3f M (%+.1f%%)\n\n", pf*f/1e6, 100*(pf-h)/h;
    printf "Into a target that counts fragments and writes (without \x60.uncounted()\x60): %.3f M (%+.1f%%)\n\n", ct*f/1e6, 100*(ct-h)/h;
    printf "Where they go, in the default release build (%.3f M per frame: several codegen units, no\nLTO, the stages\x27 functions kept apart):\n\n", d*f/1e6;
    printf "| stage | instructions per frame | share |\n|---|---:|---:|\n";
    row("vertex stage (transform, outcodes, projection), once per vertex", pr);
    row("triangle walk (fetch, trivial reject, culling, clipping)", wk - fc);
    row("flat shading per triangle (Lambert from the kept face normal)", sh);
    row("span set-up (sorting, edge steppers)", sp);
    row("depth walk set-up, rows and pixels (edge stepping, depth test, writes), and the rest of each triangle\x27s work (its inputs, its colour\x27s conversion)", fc - sh - sp);
    row("rest of draw_scene", d - pr - wk);
}
function row(name, v) { printf "| %s | %.0f | %.1f%% |\n", name, v * f, 100 * v / d }')
echo "$counted_line"
echo "$line"
echo "$report"
echo "$timing"
# HOST_GOAL: fail when the headline's instructions per frame exceed it (.ci/run: issue #7's
# goal on x86-64, as for the Cortex-M cores' counts).
if [[ -n "${HOST_GOAL:-}" ]] && ! awk -v h="$headline" -v n="$frames" -v g="$HOST_GOAL" 'BEGIN { exit !(h / n <= g) }'; then
    echo "the x86-64 reference frame takes $((headline / frames)) instructions, above $HOST_GOAL (issue #7)" >&2
    exit 1
fi
if [[ $doc == 1 ]]; then
    if command -v qemu-system-arm >/dev/null; then
        stages=$(python3 bench/mcu/stages.py)
    else
        stages="(Not measured here: bench/mcu/stages.py needs qemu-system-arm, see bench/mcu/run.sh setup.)"
    fi
    cat >docs/performance.md <<DOC
# Performance: the reference scene

Regenerated by \`bench/host.sh --doc\` (x86-64 counts by callgrind; they are exact and
repeatable, wall times are not) and \`bench/mcu/run.sh\` (emulated Cortex-M, see
[footprint.md](footprint.md)). The x86-64 count is of a build made as the firmware is, and as
the Rust peer below was: fat LTO, one codegen unit (Cargo profile \`bench-lto\`), and like the
firmware presets with the crate's \`asm\` feature (its row loop in x86-64 assembly; the count
without it follows the headline). The default
release build splits the crate into several codegen units and links without LTO; its count is
given beside the stage breakdown, which needs the function boundaries it keeps, and it moves by
about 1% when code moves between modules (what is inlined depends on the split). The scene is
bench/SCENE.md's tilted torus at 320x240: flat Lambert, u16 depth, back faces culled; one frame
is the drawing, clears excluded, into a target that counts no fragments (\`ColorDepth::uncounted\`:
the scene needs no counts, and the firmware presets draw the same way; what counting them
costs is given below the headline). The mesh keeps its face normals, found once before the
frames (\`Mesh::with_face_normals\`, 12 bytes a triangle), and \`FlatKept\` lights each face
from them, as the \`full\` firmware preset does: the torus does not change shape, so its
normals need not be found again every frame; the colours are \`Flat\`'s, which finds each
face's normal from its positions every frame (its count follows the headline).

## x86-64

$report

Median host time, the fixed-point renderer and the crate's f64 reference renderer (per-pixel
edge functions over bounding boxes, the same vertices) in one run:

\`\`\`text
$timing
\`\`\`

## Numbers to beat

| renderer | x86-64 instructions per frame | Cortex-M4F | Cortex-M0 class |
|---|---:|---:|---:|
| fixed3d today | $(awk -v d="$headline" -v n="$frames" 'BEGIN { printf "%.3f M", d / n / 1e6 }') | $(grep -E '^\| .full. \| \| thumbv7em' docs/footprint.md | awk -F'|' '{v=$8; gsub(/[ ,]/,"",v); printf "%.3f M", v/1e6}') | $(grep -E '^\| .full. \|.*\| thumbv6m \|' docs/footprint.md | awk -F'|' '{v=$8; gsub(/[ ,]/,"",v); printf "%.3f M", v/1e6}') |
| goal | 1.0 M | 1.0 M | 2.0 M |
| best C++ MCU library measured | 2.17 M | 2.03 M | 43.3 M |
| best C fixed-point MCU library | about 3.6 M | 3.61 M | 8.94 M |
| a Rust float software renderer | 7.96 M | 7.78 M | 32.1 M |
| floor: depth-test and write each covered pixel once | about 0.4 M | | |

## Cortex-M, stage by stage

The same frame on the emulated cores of [footprint.md](footprint.md), cut short after each
stage in turn by \`bench/mcu/stages.py\` (a copy of the crate with one early return; each
stage is the difference between two cuts, good to a few per cent of the frame since every cut
moves the code around it a little). The copy lives at another path than the checkout, and
counts the same: the firmware benchmark is a member of the crate's workspace, so that the
firmware no longer depends on where a checkout lies (a path dependency outside the workspace
was hashed by its absolute path into every symbol name, and at one commit of issue #7 the
M4's frame measured 2.29 M in some checkouts and 2.34 M in others for the same source):

$stages

## Where the rest goes, and what would take it

- **Pixels**: a shift, a compare and two stores each (x86-64: about 10 a fragment; the
  compiler's loop on the Cortex-M4 12, on the M0 10: on every core the colour does not
  stay in a register beside the row loop's state, one load a written pixel; Cortex-M compares
  depths in 32 bits so that the stored halfword needs no masking). The \`asm\` feature's
  hand-written loops, which the firmware presets have, take nine on both cores (seven for a
  fragment that loses on the M0), and on the M4 (and M7: the DSP extension's halfword
  instructions) an uncounted span's pixels two at a time, 13 instructions for two
  (\`pixel_pairs!\`: both depths in one word, both stored ones loaded in one, unaligned where
  the span starts at an odd column, one \`usub16\` and a \`sel\` each for the depths and the
  colours that win, both words stored back; a span of odd length takes its first pixel
  alone): the frame 4.7% fewer instructions (1.151 M → 1.097 M); x86-64's takes two pixels a turn, the second at the next
  cells' displacement, so that one index step and branch serve both: eight a written
  fragment, six one that loses, and a span of odd length takes its first pixel apart, four
  more (its frame 1% fewer instructions than one pixel a turn; the torus' spans are 4.8
  pixels long on average; on the M0 a second pixel's cells need two more registers, which
  the row loop does not have, or an index step of its own, which costs as much as it saves).
  On x86-64 a span now takes its cells eight at a time in SSE2, its baseline, wherever the
  buffers hold 7 cells after the triangle's rows (all but a triangle on their last row):
  each window of eight cells from the span's first is read, merged and written back whole
  (\`window_rows!\`: the depths of its lanes from the walk broadcast and the steps to each
  lane, less 2¹⁵ so that a signed comparison of words orders them, the lanes beyond the
  span held off by a bound, the depths written the lesser of each pair and the colours
  merged under the winning lanes), 21 instructions a window (19 for a whole one) and 4 to
  enter the span: about 25 for the torus' span against about 40 a pixel at a time, and 17
  a triangle to set up its registers. The frame 3.5% fewer instructions (1.175 M → 1.134
  M; SSE4.1's unsigned minimum and packing would take two or three a window fewer, but
  are not x86-64's baseline). Since: the depth walk kept as the row's lanes at column 0
  (one \`paddd\` a row), a window's high lanes its low ones plus four steps, and for a
  triangle within the columns each span end by one \`pextrw\` and the row's test by the
  sign of i = x0 − x1, which the span needs anyway (2.3% together); strictly nearer and
  uncounted, the losing lanes by \`pcmpeqw\` of the lesser depth with the stored one, so
  that the colours \`new ^ ((new ^ old) & loses)\` need no copy of the old ones (0.8%). A
  row within the columns now takes 10 instructions, a span's entry 8 and a window 19 (18
  for a whole one).
  A target that counts fragments (the default, for \`Stats\`) adds each span's length and counts the fragments that fail, one count
  carried through every span of a triangle (writes are the fragments less the failures; a
  count of the writes from zero for each span cost the M4 1% to 3.4% of its frame, the M0
  1%); without the counts (\`.uncounted()\`, a type) the M4 takes 5.5% fewer
  instructions per frame (10.4% with the \`asm\` loops, which then need no count either and
  take the pixels in pairs), the
  M0 4.1% (3.0% with its \`asm\` loop), x86-64 1.6% (the counts hold registers in the row
  loop, and since the reciprocal square root took one Newton step the uncounted compiled
  pixel loop keeps its colour on the stack, where it had it in a register, 3.1% before).
  With the \`asm\` feature x86-64's windows count too: each span's length added on entry,
  each window's winning lanes into a register's words (one \`paddw\` of the mask), their
  sum once a triangle (for rows of at most 2¹⁵ windows, so that no lane's count leaves its
  word; others take the pixel loop): the counted frame 2.8% fewer instructions than in
  that loop (1.185 M → 1.152 M), then 3.5% above the uncounted one (now 5.7%: the
  uncounted windows' merge by the losing lanes, above, needs the winning ones to count). The depth test
  is a type too (\`Less\` or \`LessOrEqual\`): as a run-time flag it cost a load and a
  branch per span, 0.7% of the M4's frame, 1% of x86-64's, 0.3% of
  the M0's, and linked both loops. The floor of the scene is about 0.4 M on x86-64. On the M4 the same loop out of line
  took 12 per pixel (predicated, every register its own), but the call and its arguments
  cost each span more than that saved (measured before the failure count: 2% more per
  frame); with the \`asm\` loop in line the pixels take about 0.28 M there.
- **Rows and span entries**: every row steps two edges, clips the span to the target (on
  the M4 only for a triangle that crosses its left or right side), and
  moves the depth start and the row's place in both buffers; a row with pixels also checks
  the span against the buffers (one bounds check serves both: same length), takes the depth
  at its first pixel from the row's value at column 0 (one 32-bit multiply and addition:
  \`RoundedRows\`, the plane through the snapped vertices with its gradients rounded once to
  the loop's unit, 2⁻¹⁵ of a depth step, set up from the first vertex's depth by one division
  of each gradient's numerator with a 32-bit quotient, every value within
  (|x − x_r| + |y − y_r|) / 2 + 5/4 of that unit of the exact plane; the exact start took the
  plane in Q1.44, with 64-bit quotients, and at each span a 64-bit product on the M4 and
  x86-64, two 32-bit products and six words of quotients and remainders on the M0: 4.4% of
  the M4's frame, 5.2% of the M0's, 0.5% more on x86-64,
  the same image) and counts fragments and failures. On Cortex-M0 an
  edge is an exact Bresenham quotient and remainder (five words, and a correction when the
  remainder wraps). On Cortex-M3/M4, which divide words in one instruction, it is the
  numerator itself in one word, stepped by one addition and divided once a row
  (\`DivideStepper\`: the span end is a base column plus the quotient, exact while
  (|dx| + 31) × dy ≤ 2³² in sub-pixels, which every triangle within the pipeline's
  ±(2¹⁵ − 16) meets, so its row loop has no check; larger triangles from \`triangle_spans\`
  are set up again every ⌊(2²⁷ − 1) / width⌋ rows, in a copy of the row loop out of line):
  5.8% of the M4's frame and 450 bytes, and 0.7% more with the edges stepped before the
  row's span rather than after it (their words are then dead across the pixel loop). An M4
  divide takes 2 to 12 cycles where most instructions take one, so counted in cycles the
  gain is smaller. On x86-64 an edge is one 64-bit word, the quotient in its high half and
  the remainder as a fraction of 2³², rounded up, in its low half, so one addition a row
  (\`FractionStepper\`: exact while rows × (16 × height − 1) < 2³², always for the
  pipeline's triangles, and others are set up again from their vertices that often; 5% of
  x86-64's frame). On the M4 (before \`DivideStepper\`) its set-up's fractions in 32-bit
  words (a reciprocal estimate and a corrective divide, or two divides of 16-bit digits)
  cost more than the rows saved: 6.5% and 5.2% more per frame, 900 bytes more flash (the row
  step went from 28 instructions to 16, but each edge's set-up took 22 more, and the
  triangle's own about 77 more: copies of the wider steppers, the re-seeding checks). About
  49 instructions per row with pixels on the M4 (29 for every row, 20 more for its span's
  bounds check and the \`asm\` loop's set-up; 61 while fragments were counted, 69 before
  \`DivideStepper\`), where the arithmetic needs about 25: the rest moves the row's state (the edges, the depth walk, the clip column, the
  buffers) between registers and the stack around the pixel loop. With the \`asm\` feature
  (the firmware presets have it) the M4's whole row loop is Thumb-2 too, for a solid colour
  into u16 depth: 13 instructions a row (18 for a triangle that crosses the target's left
  or right side, whose spans are clamped) and 6 more to enter a span (20 a row while each
  edge had a base to add, to keep its numerator unsigned: now the numerator is signed and
  divided so, and the loop without the clamps keeps the run's end in the register the other
  loop gives the width; the frame 2.8% and 0.6% fewer instructions, 1.097 M → 1.059 M; 17 a
  row until both edges' numerators, steps and denominators were interleaved in the block,
  \`RunEdges\`, and loaded by one \`ldm\` into r0 to r5, which the loop then names itself:
  6 instructions for both span ends instead of 10, 2.9% fewer, 1.059 M → 1.029 M). It reads
  the triangle's constants in pairs (\`ldrd\`) from one block in memory and stores the two
  numerators back with one \`strd\`, which leaves thirteen registers for the row and the
  pixel loop together;
  the runs above and below the middle vertex go through it in one call, the lower short
  edge set up beforehand and copied over its side by the loop. The three edges are set up
  from the triangle's rows (\`TriangleRows::runs\`) as the block is built, where they were
  first the spans' edges, copied in after (that cost x86-64 1.9% of its frame, the M0 0.8%,
  the M4 0.3%). Its set-up (the edges copied into the block, the buffers' cells checked once
  a triangle, by one product, the end row's: the M4 0.35%, the M0 0.1%, x86-64 0.27% more;
  the clip's columns not compared with the buffers', which a \`ColorDepth\`'s always span:
  x86-64 0.6%, the M4 0.2%, the M0 0.17%) costs about 60 instructions a
  triangle more than the compiled loop's (\`profile.py\`), where a triangle's 8 rows save
  about 20 each: the frame 3.9% fewer instructions (1.722 M → 1.655 M), about 500 bytes
  more flash. Made of two runs a triangle, each set up apart, it saved 1.5%. (In the stage
  table the M4's fill set-up includes that set-up and the lower short edge's, which the
  compiled loop sets up among its rows, and so does the M0's below; the cut before the
  assembly moves more code than the others, so that on both cores the rows, span entries
  and fill set-up are best read together.)
  On the M0 the \`asm\` feature's row loop is Thumb-1, a naked function: inline assembly
  there gets six registers and the pixel loop needs eight, so the function saves r8 to r11
  and lr and keeps the step along a row, the colour, the depth walk, the row's address, the
  width and the block's address there. It walks the same exact edges from the same kind of
  block, each edge's five words loaded by one \`ldm\` (1.3% of the frame against a load a
  word): 25 instructions a row (2 more when an edge's remainder borrows; a span crossing a
  side of the buffers clamped out of line) and 10 to enter a
  span, against about 60 for the compiled row loop; its pixel loop 9 instructions (7 for a
  fragment that loses) against the compiler's 10, the colour moved into a low register for
  each span (0.4%). The M0's frame 5.1% fewer instructions (3.536 M → 3.357 M), 510 bytes
  more flash; its set-up writes the triangle's edges with the block, the lower edge a copy
  of the left one until a split replaces it (clearing that edge is a library call a
  triangle: 0.9% of the frame; clearing all three and copying two in after, 1.4%) and checks
  the run's cells without 64-bit products (2%). On Cortex-M the compiled rows run
  in one loop that checks for the middle vertex's row every time: in two runs, above and
  below it (as x86-64 keeps them: one loop costs it 6%), each run's entry moved the row
  state between stack slots, 26 instructions a run on the M0 (one loop: 0.7% fewer
  instructions per frame on the M0, 1.3% on the M4; one test a row instead, against the
  next row where the split, a re-seeding or the end falls, measured 4.7% more on the M4).
  On x86-64 the compiled loop steps the edges out of line,
  which leaves the pixel loop its registers (3.3% of the frame); on Cortex-M the call costs
  more than it frees. It still takes about 45 instructions a row, 52 with pixels, and
  about 10.2 a fragment (its unrolled pixel loop reloads the colour from the stack, and a
  span's odd pixel goes apart). With the \`asm\` feature x86-64 runs the whole triangle's
  rows in assembly too (src/target/x86_64.rs), from the Cortex-M loops' block and set-up:
  both edges' walks stay in registers (their steps in the block), 14 instructions a row, 6
  to enter a span, 7 a fragment and 2 more a write (later 5 and 2, and 2 for each two
  pixels; now windows of eight cells, above): the frame 10% fewer instructions (1.660 M →
  1.493 M), where the same block walked by a compiled loop (for targets without assembly)
  had measured 3.7% more. Both walks now lie in one SSE2 register, their steps in
  another: one \`paddq\` steps both and four instructions take their high halves, 5 a row
  where they took 6 in two general registers (0.64%, 1.134 M → 1.127 M); the lower short
  edge takes its side's lanes. For a triangle within the columns each end is one
  \`pextrw\`, the low word of its walk's high half, which holds it whole (the ends and the
  step 3 instructions a row: 1.4%, 1.056 M → 1.041 M). In the
  \`asm\` loops the clamps to the columns took 4 or 5 instructions a row (without them the
  M4's frame measured 2.5% fewer, the M0's 1.0%, x86-64's 2.2%): the M4 takes a second loop
  without them for a triangle within the columns (one unsigned test a vertex,
  \`TriangleRows::within_columns\`: 1.5% net, about 200 bytes), the M0 tests both ends
  of every span by two unsigned comparisons and clamps out of line (a second loop and its test
  gained it only 0.3%, 216 bytes), and so does x86-64 a pixel at a time; its windows have
  a second loop for a triangle within the columns, one comparison a row (0.3%, the test
  included). A copy of the compiled row loop
  without the clamps had measured 0.7% more on the M4 and 12% more on the M0. An
  earlier fixed-point walk for small triangles only (exact while rows × 16 × height ≤ 2¹⁶,
  in a second copy of the row loop) measured no gain on the M4, 1.8% more on x86-64 and
  850 bytes more flash. Two passes
  instead (the ends of up to 16 rows into a buffer, edge by edge, then their first depths,
  then the spans) cut the spans' own traffic to about 18 instructions a row on the M4, but
  the passes before them cost as much again, and the buffer's set-up per triangle more:
  measured 5% to 15% more per frame.
- **Per triangle**: the depth walk's two steps (divisions of numerators below 2⁵² by the
  doubled area, with 32-bit quotients: on Cortex-M0 by two 15-bit digits from a 16-bit
  reciprocal, as a vertex's below (\`ShortQuotients::round_below_2_30\`, for doubled areas
  below 2²⁹ and steps below 2³⁰: 99% of the torus' triangles, the magnitude rounded without
  the saturation that only magnitudes past 2⁶³ reach: 0.35%), about 200 instructions a
  triangle with the divisor's 16-bit reciprocal, where one reciprocal to 32 bits and its
  64-bit products, which the rest take, cost about 250 (the frame 2.4% more; an earlier form of the digits, not in line, had
  measured 0.8% more than the reciprocal); on the M4 by 32-bit divides where
  the numerator allows; the exact Q1.44 plane, two divisions with 64-bit quotients, only for
  the triangles the walk does not take: a vertex at the far plane, a step beyond 32 bits)
  and three edge steppers (two
  divisions each; neither the area, which the pipeline never draws at zero, nor the clip
  rectangle, empty of spans when it has no rows or columns, tested there: x86-64's frame
  0.9%, the M4's 0.5%, the M0's 0.3%; on the M0 without \`asm\` (with it in
  \`thumb1::triangle_runs\`, below) an edge's quotients from −16 to 15 found
  by subtraction before a library division, one loop of a test, a subtraction and a count
  for both signs (a negative numerator counts the subtractions of ⌈−n / d⌉): 0.4% against
  quotients to 8, and the loop 1% against one that told the signs apart at 9 instructions a
  turn; the flatter lines of a wireframe try 2: 16 cost the \`wire\` preset 3.6%; with the
  \`asm\` feature Cortex-M3/M4 sort the corners, find the rows and set up the three edges in one
  block of Thumb-2, \`thumb2::triangle_runs\`, about 150 instructions (139 since its edges
  have no base; about 120 since it loads the corners' x once for all three edges and takes
  the long edge's side from the area's high word, 0.5% and 0.3% fewer; and it writes the
  lower edge's place into the row loop's block itself, where the Rust read a flag back and
  stored it: 1.0% fewer, more than those five instructions a triangle, as fewer values wait
  around the assembly, 1.018 M → 1.007 M), and the depth walk in
  line right after it: the M4's frame 1.9% fewer instructions, about 1.1 KB, and no fewer
  with the depth walk's set-up out of line, 0.2% more with the row loop's block kept by the
  target instead of made for each triangle, and 1.2% fewer again with that block not
  cleared before each triangle (its runs from the assembly, every other field written once
  into uninitialised memory); checked on random triangles of every case by the
  \`variants\` preset; on the M0 the same in one naked function of Thumb-1,
  \`thumb1::triangle_runs\`, with the exact walks its row loop steps, each edge's quotients
  by subtraction and past sixteen by a long division of its own: about 257 instructions a
  triangle, 87 fewer than the compiled set-up with its edges' calls and the runs' copy into
  the row loop's block, the M0's frame 3.65% fewer, 2.278 M → 2.195 M, for 304 bytes), then
  flat shading. By \`FlatKept\`, as here, from the face's normal
  kept in the mesh
  (\`Mesh::with_face_normals\`, once: its direction at 15 bits and the reciprocal of its
  length, 12 bytes a triangle): a product with each light, which decides whether the face
  turns to it wherever it lies beyond ±2³¹ (within that band, where rounding the direction
  could change its sign, the face is lit from its positions as \`Flat\` lights it; no face
  of the torus is), and the cosine from it and the reciprocal; the same colours as
  \`Flat\`, the M4's frame 5.7% fewer instructions, the M0's 7.0%, x86-64's 7.1%. (As
  a path inside \`Flat\`, read where a mesh keeps normals, it cost meshes that keep none 2%
  on the M4 and 0.5% on the M0, its registers moving around the whole triangle set-up: a
  type of its own costs them nothing. The colour found in the walk and handed to the fill
  instead measured 0.5% fewer on the M0 and 0.6% more on the M4, and 3% more for \`Flat\`;
  the kept path out of line 1.3% more on the M4; the face's index handed down in place of its
  triangle, for the shading to look both up, 0.8% more on the M0; the face's place found
  from its triangle's address, not counted by the walk, 0.7% more on the M4 and 0.15% on the
  M0; the walk's count of culled faces, which its two more loop variables moved to memory,
  kept in a local for each object, 1.1% more on the M4 and 0.5% on the M0; two walks, one
  with the kept normals beside the triangles and one without, 0.2% fewer on the M4 for 330
  bytes and 0.6% more on the M0; the object's colour under the ambient light alone found
  once per object for the faces turned from every light, a fifth of those drawn, instead of
  for each, 0.4% fewer on the M0 and 0.4% more on the M4.)
  By \`Flat\`, the face normal (a cross
  product of 32-bit edges; on 32-bit cores, of edges within ±2¹⁵, in 32-bit words: on the M4
  since its edges divide, 0.7% of its frame; on x86-64 1% more; taken as it is, within
  ±2³¹, where it was halved from 2³⁰ on: the M4 1.3%, the M0 0.2%; untested where every
  edge of the mesh lies within ±(2¹⁵ − 1), \`Mesh::edge_extent\`, found with its index
  check: the M4 0.45%, the M0 0.3%) and Lambert against the lights (grey
  ones: one sum for the three channels, in a 32-bit word when every channel lies in [0, 1]
  (\`Lighting::in_words\`: each term below 2¹⁷, the sum below 2³¹; the M0's frame 0.4%
  fewer instructions than in 64 bits, the M4's and x86-64's 0.3%); at most N of them, which
  bounds their loops: for the torus's one light a test, not a loop, 1% of the M4's frame
  and 0.7% of the M0's) without a unit normal. A face turned from every
  light gets the ambient colour (on Cortex-M0 that test takes the high halves of the normal
  and the light, three 32-bit products, wherever they decide it: 1.2% of the frame); for
  the others each light's cosine is the direction, shifted to 15 bits, times the light over
  its length (\`NewtonDirection\`: one multiply by the reciprocal square root, where the
  unit normal took a product, a rounding and a clamp per component before its own product
  with the light: the M0's frame 0.7%, the M4's 1%, x86-64's 0.35%; the root from a seed on
  the chord between two entries of a 65-entry table, within 3.6·10⁻⁴ of it, and one Newton
  step with its second-order term, which leaves it at most six units of 2⁻⁴⁵ above the root,
  never below, where two steps from a table's seed within 1.6% left it up to 389 units below
  (M9's worst from 1.6·10⁻⁷ to 3.3·10⁻⁹): the M0's frame 1.6% fewer instructions, the M4's
  0.16% more and x86-64's 0.37% more (2.5% more without \`asm\`, whose compiled pixel
  loop then keeps the colour on the stack); the entries take the top bits masked to six as
  an index, and the seed bounds 3 − m·y² to a word, so that neither needs a clamp or a
  bounds check; on 32-bit cores a cosine is taken from its low word, below a
  clamp it never reaches: the M4 0.7%, the M0 0.5%; on Cortex-M0 the 15-bit products
  take two multiplies each where the unit normal's took four: 1.7% of the M0's frame, 0.6%
  of the M4's, 0.3% of x86-64's, for 300 to 450 bytes; the colours are the unit normal's
  for every face of the torus). The lights are turned into model space once per object
  when the model matrix is a rotation times a scale (no normal matrix per face). Not kept:
  that usual face (lit in model space, short edges, Newton's normalisation: one test a
  triangle of a fact known once per object) in line with the others' paths out of line
  (the M0's frame 1.6% fewer instructions, x86-64's 1.5%, the M4's 0.3%, but 0.7 to 1.1 KB
  more flash, and the \`flat\` preset's cube, whose edges are long, 1.6% more on the M4;
  measured again on x86-64 and the M0 alone, after the M0's quotient digits were written
  out: the M0's frame 1% more, 800 bytes, x86-64's 0.1% fewer), and
  the culled triangles counted after each object from the other counts instead of one by one
  (the M4's and the M0's frames 0.05% fewer, x86-64's 0.2% more), and the walk's three tests
  of a triangle's indices as one test of the largest, as flat shading reads the model
  positions (the M4's frame 0.5% more, x86-64's 0.5%), and the walk of an object inside every plane in two
  passes a batch of 32 triangles, culling with no call in its loop, then filling those it
  kept (the M4's frame 2.3% more, the M0's 0.8%, x86-64's 1.6%: the second pass's fetches
  and bookkeeping cost more than the first's registers saved), and \`fill_face\` taking
  references to the cached vertices instead of a copy of their points and depths (the M4
  0.55% more, the M0 0.2%, x86-64 1%), or in line in the walk (the M4 3.5% more), and
  Lambert forming its colour once, from three intensities, after its paths meet (the M4
  0.9% more, the M0 0.6%, x86-64 0.6%: the channels, packed on each path and taken apart
  by the conversion, cost less than the three registers). On the M4
  the culling's doubled area and the depth walk's gradient numerators are sums of two
  products with one side negated, a widening multiply and a multiply-accumulate where a
  difference takes two instructions more (0.8% and 0.5% of its frame), and an edge's set-up
  takes its height as it is, positive for every edge with rows, its stepper keeping its own
  denominator positive (1% of the frame, against a second guard). On x86-64 the triangle
  walk is compiled once per culling mode, the mode a constant (0.5% of its frame; on the M0
  that cost 1.4% more instructions and 1.4 KB, on the M4 it saved 0.2% for 1.3 KB, so both
  read the mode). With the \`asm\` feature the walk of an object inside every clip plane,
  culled to its front faces, skips the back faces in assembly (\`FrontFaces::next_stop\` in
  each core's module, its state in \`target/asm_faces.rs\`): each triangle's indices
  (unchecked: \`Mesh::new\` checked every one), points and doubled area in one loop that
  stops only on a face to draw, whose corners it copies for \`fill_face\`, or one of zero
  area: 22 instructions a back face on the M4 (21 with the area in words, every side of
  such an object within ±2¹⁵: 0.04% fewer; a front face's corners copied since by one
  \`ldm\` and one \`stm\` each, 0.48% fewer), where the compiled walk took about 49, 29 on
  the M0 (about 65), 24 on x86-64 (about 50), each keeping its state on the stack around
  the call it makes for the faces it draws: the frames 3.4%, 2.8% and 3.3% fewer
  instructions, 300 to 450 bytes; that walk out of line (its loop its own registers) 0.24%
  fewer again on the M4 and x86-64 (on the M0 0.26% more, so there it stays in line). In
  Rust the same skip as a function of its own measured the M4's frame 6% more, in line 2.8%
  more; \`fill_face\`'s body in line in the walk in assembly, the M4 2.9% more, the M0 3.2%,
  x86-64 2.6%. At the firmware's opt-level "s" an iterator's sum or
  \`array::map\` over three components stays a loop, so this code writes them out (dot
  products, the normal's largest component, each vertex's tuple: 4% of the M4's frame; the
  reciprocal square root's Newton steps, when it took two: 0.3% of the frame), and a flat
  triangle hands
  \`fill_face\` no vertex colours
  (the shadings that do not interpolate them share one array of zeros: 1% of the M4's
  frame).
- **Per vertex**: the transform (twelve 32x32→64 products, summed and rounded once, each row's
  sum started from its translation with the rounding's half added, so that on the M4 every
  product is a multiply-accumulate: 0.5% of its frame, x86-64's 0.4%), then the
  outcode and the projection from one reduction (three divisions by \`w\`, the depth's
  without a check of 0 ≤ z ≤ w, which the near and far planes give: the M4's frame 0.3%, the
  M0's 0.9%; inside the guard
  band the screen offsets in 32-bit words and without clamps, which the band and the
  largest viewport make no-ops: 0.6% to 0.9% of the frame). Where products are long
  multiplies (x86-64, Cortex-M4) a mesh whose clip coordinates are known to fit 32 bits goes
  from the transform to the projection in one path, in line (the M4's frame 1.6%, x86-64's
  0.7%). On Cortex-M0, whose products of 32-bit factors are routines of four multiplies, the
  transform takes two 32-bit multiplies a term with 32-bit sums instead
  (\`SplitTransform\`: the entry times the coordinate's high part and times its low \`k\`
  bits, \`k\` chosen once per object so that both sums stay words, for meshes up to about a
  thousand units across at unit scale; larger ones take the 64-bit products: first as three
  multiplies a term, the coordinate's high half times the whole entry and the entry's
  halves times its low half, which held four times further out, 4.8% of the frame for 460
  bytes, split at bit 15 rather than 16 1.3% more; the two a term 1.7% fewer instructions
  again, and a few bytes fewer; for an object
  known inside in words the transform's words go to the projection in line, \`project_words\`,
  where the general path is a call taking 64-bit coordinates: 1.6% of the frame for about
  800 bytes, 0.9% with one copy of the transform before both paths), and the
  divisions by \`w\` are short ones in 32-bit words (\`ShortQuotients\`: a 16-bit
  reciprocal of w's top bits, from the seed table and one Newton step, which leaves it exact
  or one below, and one test of its remainder (a loop of up to four steps either way cost
  0.8% of the frame), then one multiply estimates each 15-bit quotient digit to within 3
  below (for quotients up to 2¹⁵, every caller's, as \`ShortQuotients\`' note proves), the
  remainder is exact in one word, and up to three subtractions written out finish the digit
  (as a loop of up to five, its count in a register, 2.1% of the frame more; five written
  out 0.2% fewer again for 240 bytes), and x and y take one digit each,
  the depth two: 6.1% of the frame for 590 bytes,
  against a reciprocal to 32 bits and 64-bit products; the bounds that make a digit exact,
  which every numerator of a vertex inside the planes and the guard band meets, are not
  tested: 2.4% of the frame). No vertex of an object is tested against the clip planes
  where its mesh's bounding sphere (\`Mesh::radius\`, about the model's origin) lies inside
  them all, found once per object and frame for meshes of 128 vertices or more
  (\`ScreenMap::known\`: a plane's distance is an affine function of the point, least on the
  sphere at \`a·t − |g|·radius\`, less half of \`Σ|a_i|\` for the coordinates' rounding, |g|
  bounded above by a root in 32-bit words; smaller meshes cost more to test than their
  vertices' outcodes: the M4's frame 2.2% fewer instructions, the M0's 2.1%, x86-64's 1.9%,
  about 800 bytes). Where the sphere also bounds \`x·half_w\` and \`y·half_h\` within words and
  \`w\` below 2¹⁹ (\`Known::InWords\`), each product is one 32-bit multiply (the M0 0.7%) and,
  with a divide instruction, the divisions take words untested (the M4 0.8%, x86-64 0.5%,
  the depth there one 64-bit division; on the M0 a digit from the low word alone measured
  0.4% more). With the \`asm\` feature the M4 takes such an object's vertices without lit
  colours in a naked Thumb-2 function (\`thumb2::project_known_in_words\`): the transform,
  the two rounded quotients and the depth's three digits in 65 instructions a vertex, each
  row of the matrix read from a block by one \`ldm\`, each result stored as it is found,
  where the compiled loop took about 125, reloading the matrix from the stack for each
  vertex: the frame 4.1% fewer instructions (1.219 M → 1.170 M), about 420 bytes. Now 61:
  the block's rows scaled by \`2^(16 − shift)\` and each point by \`2^shift\` as it is
  loaded, each clip coordinate is its sum's high word, where taking the sum's bits 16 to
  47 took two instructions a row (0.57% fewer, 1.0055 M → 0.9999 M; the shift the largest
  up to 16 that keeps points and coefficients in words, declined near \`fits_32_bits\`'
  bound, where the Rust loop takes the object). The
  stage was about a sixth of the M0's frame, about 380 instructions a vertex
  with the frame's matrices (about 330 in its loop), most of them the transform (about 135)
  and the divisions (about 135 with the reciprocal); with the \`asm\` feature the M0 takes
  such an object's vertices in a naked Thumb-1 function too
  (\`thumb1::project_split_in_words\`: \`SplitTransform\`'s rows, each read by one \`ldm\`,
  the high parts' sums pushed and the low parts' rounded onto them, then w's
  \`ShortQuotients\` and the three rounded quotients), about 263 instructions a vertex: the
  frame 3.6% fewer instructions (2.195 M → 2.115 M), about 870 bytes (checked by the
  \`variants\` preset's \`vertices\`, a hash of every vertex's position and depth). Not kept: Lambert's rounded dot product in
  32-bit parts (no fewer instructions than three calls of the four-multiply product, 310
  bytes more); \`NewtonDirection\` on Cortex-M0 alone, with the reciprocal found only when
  a light first faces and no test before (1.7% there, 224 bytes less, the M4 unchanged),
  since its cosines differ from the unit normal's by up to 3 units of 2⁻³⁰, and a colour
  could then differ between the host and the firmware (rule R10); on every core, that form
  cost the M4 1.7% more (its per-light closure left the loop, its state on the stack), and
  1% more with each cosine found in one loop for both the grey and the per-channel sums.
  Nor, on the M0, measured after its quotient digits were written out: an edge's
  subtractions with their first three turns written out (0.2% more, 360 bytes) or as a
  loop that counts the quotient alone (0.15% more), the edge set-up in line (0.8% more,
  1.5 KB), flat shading out of line (1.7% more), the reciprocal square root's products
  of halves in line (0.2% more, 240 bytes), and a vertex's divisor prepared without its
  range test where \`Known::InWords\` bounds it (0.4% more). On every core, not kept: the
  usual face's direction (lit in model space, short edges) in line and every other one
  through a call (the M0 0.3% more, the M4 0.4%), and the first row's edges set up where
  they go, their vertices chosen first, instead of swapped after (the M0 0.5% more, the M4
  0.9%).
- **The goals**: all three are reached. The Cortex-M0's at 1,993,013 instructions a frame (\`.ci/run\`
  fails above 2.0 M), the last 12.5% (2.278 M before) from the set-up of a triangle's rows,
  the vertex loop and a small triangle's depth walk in Thumb-1 (below and above), and their
  trims. The Cortex-M4F's at 994,697 instructions a frame (\`.ci/run\` fails
  above 1.0 M), the last 6.1% from the row loop's edges by one \`ldm\` (2.9%),
  \`triangle_runs\` loading the corners' x once, finding the long edge's side from the
  area's high word and writing the lower edge's place itself (1.8%), the vertex loop's
  coordinates as their sums' high words (0.57%), the kept face normals as a slice and the
  vertex colours that flat shading never reads dropped from \`fill_face\`'s call (0.47%),
  the back faces' area in words (0.04%) and a front face's corners copied by one \`ldm\`
  and one \`stm\` each (0.48%). Not kept in that round: the triangle's corners
  interleaved with their depths and written in place by the walk in assembly, read in
  place by the target (the M4 0.34% fewer, the M0 1% more), the depth walk's result written
  into the row loop's block by the assembly (0.02%), the count of drawn triangles kept in a
  register (the M0 0.13% fewer, the M4 0.66% more). Since, on the M0, a triangle's rows set
  up in Thumb-1 (\`thumb1::triangle_runs\`, above: 3.65%), and its vertex loop
  (\`thumb1::project_split_in_words\`, above: 3.6%, 2.195 M → 2.115 M); not kept there: the depth walk's
  set-up in line beside it (1.0% fewer for 1.27 KB more flash, the set-up then in two
  copies), or out of line taking the triangle itself (0.06% more), the numerators' test of
  short sides made once for all four products (0.37% more, 190 bytes), and the transform's
  high parts rounded with the low parts' sum taken from the whole coordinates' (2.1% more:
  more values live at once), and the depth walk's set-up in line with the other paths'
  walks by the reciprocal alone (1.4% fewer, 580 bytes, but \`gouraud\` 1.1% more and
  \`display\` 0.7%). Then a small triangle's depth walk in Thumb-1
  (\`thumb1::depth_walk\`, writing into the row loop's block: about 320 instructions a
  triangle where the compiled set-up took about 410 and its call, 3.75%, 2.115 M → 2.036 M;
  where the compiled set-up in line had measured 1.0% for 1.27 KB, this takes 1 KB for
  3.75%, the compiled one kept for the rest), and trims of all three: \`ShortQuotients::top\`'s
  usual shift by one branch (0.37%), the row set-up's divisions in line (0.53%), the seed
  tables' addresses from the literal pool and a half size kept (0.34%), the walk's output
  not cleared first (0.19%) and written into the block (0.33%), its sides tested once and
  only where not known short (0.19%): 1.993 M; since, the lights each face reads kept once
  an object (below): 1,983,574 on the M0 and 988,772 on the M4F. x86-64's is reached too:
  0.989 M a frame (\`bench/host.sh\`, with the \`asm\` feature), from 1.175 M at the start
  of the round before and 1.104 M at the start of the last. The round before: the windows
  of eight cells in SSE2 (3.5%), the edges' walks in one SSE2 register (0.64%),
  \`FractionStepper::new\`'s test of a 32-bit start by its low word sign-extended (0.48%),
  the windows' loop without the clamps (0.3%), the depth walk's steps by each numerator's
  magnitude over the area's (0.34%, with the runs, their edges and their steppers' set-up
  held in line: x86-64's triangle set-up, one function with LTO, sits at the edge of the
  inliner's budget, where a few instructions more anywhere took one of them out of line, 1%
  to 4.5% more) and the vertex loop of an object known inside in words in assembly (0.77%).
  The last round (1.104 M → 0.989 M, 10.4%): the triangle's set-up in line in the walk
  (\`Prepared::fill_face\`, with its paint and the target's \`fill_triangle\` held in line:
  2.0%; in line alone it had cost 2.4% more, the paint and the fill leaving the line), a
  front face's corners left in registers by the walk's assembly, where they were copied to
  memory for the call (2.3%), each span end of a triangle within the columns by one
  \`pextrw\` (1.4%), the edges' packed quotients by one \`idiv\` and its truncation's
  correction (\`target::floor_divide\`, 0.3%), an edge at most 2¹⁵ sub-pixels tall needing
  no second set-up by one comparison before \`reseed_row\`'s product (0.6%), each edge
  stored at its place rather than chosen by conditional moves (0.6%), the depth walk as the
  row's lanes at column 0 and the row's test by the sign of i = x0 − x1 (0.9%), the rows'
  cells in 64-bit words without checked steps (0.6%), the lights each face reads kept once
  an object rather than chosen for each face (0.27%), the losing lanes' colour merge
  (0.8%), the vertex loop's depth and the zero word after it by one store (0.12%: 83
  instructions a vertex) and the first row's colour address, the buffers' distance, the
  colour and the depth walk in registers rather than through the row loop's block
  (\`asm_rows::LoopStart\`, 1.0%). Not kept there: a divide by one \`div\` in assembly,
  for the compiler's test of 32-bit operands (four instructions) before the depth walk's two
  (0.04% more: its fixed registers), and by \`floor_divide\` (0.4% more), \`fill_face\` in
  line in the walk with its callees left to the compiler (2.4% more), the row loop's block
  not cleared first (0.085% fewer, for more \`unsafe\`), the depth walk's words 32-bit for
  the assembly (0.1% to 1.1% more: the compiler's code around it moved), the general span
  loop out of line (0.7% more), the cells after the rows compared once with the shorter
  buffer (0.5% more) and a saturating count by \`cmp\` and \`adc\` (0.1% more). Where the
  0.989 M go: rows and pixels in assembly about 0.32 M (10 a row within the columns, 8 to
  enter a span and 19 a window), each drawn triangle's set-up, inputs and shading about 525
  instructions (0.50 M), the walk 0.07 M (24 a back face) and the vertex stage 0.10 M.
  Before the round before, with the
  pixels at what they took (0.22 M on
  the M4), 1.0 M left
  0.78 M for 1,152 vertices, 2,304 triangle tests, 958 set-ups and shadings and about 7,500
  rows, 93% of what they took then. Per drawn triangle the M4 took about 490
  instructions outside its rows and pixels (its inputs, its flat shading, the set-up of its
  rows and of its depth walk, 0.47 M). That is not the compiler's moves between registers
  and the stack, as it looked: written by hand, the set-up of a triangle's rows (the sort of
  its corners, its rows and three edges, \`thumb2::triangle_runs\`) took about 150
  instructions (the sort 26 with its IT blocks, the rows 17, an edge 27), as many as the
  compiler's code for the same work (about 139, an edge 18, since it has no base); the 1.9%
  it saved came from the depth walk's set-up
  then running in line right after it. The same set-up written for x86-64 (its edges two
  128-bit and 64-bit divisions each, \`FractionStepper\`'s words) took about 235
  instructions a triangle where the compiled \`rows_in_range\` and \`TriangleRows::runs\`
  take about 215: the frame 1.5% more, not kept. The M4's depth walk set-up of a small
  triangle by hand (\`thumb2::depth_walk\`: its numerators by a widening multiply and a
  multiply-accumulate each, its steps by two signed divisions where a numerator fits a word,
  by three 15-bit digits otherwise, its row's start) takes about 90 instructions where the
  compiled set-up took about 105: the frame 1.4% fewer instructions (1.167 M → 1.151 M), 310
  bytes less flash (the compiled set-up for every size left out of line). The same for
  x86-64 took about 100, as many as the compiled code, and the registers it held cost the
  code around it more: the frame 3.1% more, not kept; in Thumb-1 for the M0 (a naked
  function, its digits as \`ShortQuotients\` finds them) a first form took about 340 where
  the compiled code, then in line, took about 357: the frame 0.7% fewer instructions for
  about 1 KB more flash, not kept; since the compiled set-up went out of line (a call:
  about 410 with it), \`thumb1::depth_walk\` takes about 320, written into the row loop's
  block: 3.75% for about 1 KB, kept (see the goals). A set-up and shading of about 250 instructions a
  triangle, once estimated from the arithmetic, leaves out what that arithmetic takes in
  instructions; hand-writing the rest (the depth walk's divisions, the colour) would gain
  in proportion, a few per cent. The M4's rows and pixels are already hand-written (the \`asm\`
  feature, which the firmware presets have: nine instructions a pixel, both stores
  predicated in one IT block, one index for both buffers, against the compiler's twelve, and
  13 for two in an uncounted span; 13 a row against about 49), and so are the M0's (Thumb-1: 25 a row against about 60, 9 a
  pixel against 10), and so is its vertex loop (about 263 a vertex, of which the transform
  about 118 and the divisions by w about 140). On the M0 the vertex
  stage and the depth walk's set-up, both in assembly now, come first. The rest would need less work per
  stage rather than tighter code: a cheaper rule (lighting in 16-bit arithmetic, coarser
  sub-pixels: each a change of image that \`docs/accuracy.md\` would have to show costs
  nothing), or more of what a rigid mesh keeps from frame to frame, as its face normals now
  are. Two larger changes of the work itself were sized and left: skipping the
  projection of vertices that only back faces use, found by a test in model space before
  the vertex stage, needs a margin that snapping cannot cross; bounded once per frame
  (the nearest and farthest w, the longest edge on screen) it spares 441 of the torus'
  1,152 vertices (606 are used only by back faces), about 4% of the M0's frame after a
  test per triangle, nothing on the M4 or x86-64 (there the tests of a vertex's two
  triangles cost as much as the projections they spare).
- \`python3 bench/mcu/profile.py full thumbv6m-none-eabi\` (or \`thumbv7em-none-eabihf\`)
  lists the instructions by function and the library calls by the line that makes them, and
  \`ASM=fill_face\` prints a function's instructions with their counts.
DOC
    echo "wrote docs/performance.md"
fi
