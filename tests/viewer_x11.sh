#!/usr/bin/env bash
# Drives the viewer in a real window under Xvfb, as a person would: key presses with xdotool,
# screenshots with ImageMagick, and checks that the picture changes the right way.
#   W makes the model larger; Left turns the view (the scene moves right); + widens the field of
#   view and moves nothing (whatever keys the layout needs for it); M changes the image; P saves
#   screenshots under new names; L adds a point light and K removes it; G toggles highlights;
#   the frame-time lines pause while R asks on the terminal, and a file without triangles is
#   asked again; Escape quits cleanly; without a display the viewer exits 1 with one line.
# Needs: xvfb xdotool imagemagick x11-utils libsdl2 (installed by .ci/run), and the viewer built
# with `cargo build --release --features window --example viewer`.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=target/release/examples/viewer
out=target/viewer-test
mkdir -p "$out"
fail() { echo "viewer test FAILED: $*" >&2; exit 1; }

# No display server: one line and exit status 1, not a run with no window.
set +e
env -u DISPLAY -u WAYLAND_DISPLAY timeout 20 "$bin" </dev/null >"$out/nowindow.log" 2>&1
status=$?
set -e
[ "$status" -eq 1 ] || fail "without a display the viewer exited $status, not 1"
[ "$(wc -l <"$out/nowindow.log")" -eq 1 ] || fail "without a display: $(cat "$out/nowindow.log")"
grep -q "^error: no window" "$out/nowindow.log" || fail "without a display: $(cat "$out/nowindow.log")"

display=:97
Xvfb "$display" -screen 0 1024x768x24 -nolisten tcp >"$out/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true; [ -n "${viewer:-}" ] && kill $viewer 2>/dev/null || true' EXIT
export DISPLAY=$display
for _ in $(seq 50); do xdpyinfo >/dev/null 2>&1 && break; sleep 0.1; done

# The terminal: a FIFO the test writes answers into (held open so the viewer never sees EOF).
rm -f "$out/stdin"; mkfifo "$out/stdin"; exec 3<>"$out/stdin"
shots=$out/shots
rm -rf "$shots"; mkdir -p "$shots"; echo keep >"$shots/viewer-001.png"
VIEWER_SCREENSHOTS=$shots "$bin" >"$out/viewer.log" 2>&1 <"$out/stdin" &
viewer=$!
wid=$(timeout 30 xdotool search --sync --name "fixed3d viewer" | head -1) || fail "no window"
sleep 1.5
xdotool windowfocus --sync "$wid" || true

shot() { import -window "$wid" "$out/$1.png"; }
# Fraction of the picture below the status line that is not background, overall and per half.
covered() { convert "$out/$1.png" -crop 640x460+0+20 +repage -fuzz 6% -fill black -opaque "rgb(12,12,20)" \
    -colorspace gray -threshold 4% -format "%[fx:mean]" info:; }
right_half() { convert "$out/$1.png" -crop 320x460+320+20 +repage -fuzz 6% -fill black -opaque "rgb(12,12,20)" \
    -colorspace gray -threshold 4% -format "%[fx:mean]" info:; }
changed() { { compare -metric AE -fuzz 2% "$out/$1.png" "$out/$2.png" null: 2>&1 || true; } | cut -d' ' -f1; }
hold() { xdotool keydown "$1"; sleep "$2"; xdotool keyup "$1"; sleep 0.4; }
bigger() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(b > a * 1.15) }'; }

# Stop the spinning first so that only our keys change the picture.
xdotool key Tab; sleep 0.5
shot start
hold w 0.8
shot forward
c0=$(covered start); c1=$(covered forward)
echo "W: covered $c0 -> $c1"
bigger "$c0" "$c1" || fail "W did not make the model larger ($c0 -> $c1)"

r0=$(right_half forward)
hold Left 0.5
shot left
r1=$(right_half left)
echo "Left: right half covered $r0 -> $r1, $(changed forward left) pixels changed"
bigger "$r0" "$r1" || fail "Left did not turn the view to the left ($r0 -> $r1)"

# + is Shift and = on this layout: the field of view widens, the camera stays where it was.
view() { { grep "^view:" "$out/viewer.log" || true; } | tail -1; }
fov() { view | sed -E 's/^view: fov ([0-9.]+),.*/\1/'; }
eye() { view | sed -E 's/.*eye //'; }
[ -n "$(view)" ] || fail "releasing a key that moves the camera printed no view line"
f0=$(fov); e0=$(eye)
hold plus 0.8
f1=$(fov); e1=$(eye)
echo "+: fov $f0 -> $f1, eye $e0 -> $e1"
awk -v a="$f0" -v b="$f1" 'BEGIN { exit !(b > a + 10) }' || fail "+ did not widen the field of view ($f0 -> $f1)"
[ "$e0" = "$e1" ] || fail "+ moved the camera ($e0 -> $e1)"

xdotool key m; sleep 0.6
shot mode
n=$(changed left mode)
echo "M: $n pixels changed"
[ "$n" -gt 2000 ] || fail "M did not change the image ($n pixels)"

# In Gouraud mode (3), L puts a point light at the camera and K takes it away; G turns
# highlights on and off again. Each first key changes the scene, each second brings back the
# scene from before the first, pixel for pixel (the status line, which shows the message and
# the frame time, is left out).
scene() { convert "$out/$1.png" -crop 640x460+0+20 +repage "$out/$1-scene.png"; }
# press KEY NAME: presses KEY, shoots the scene as NAME and prints how many pixels differ
# from the scene before the toggles.
press() { xdotool key "$1"; sleep 0.6; shot "$2"; scene "$2"; changed plain-scene "$2-scene"; }
xdotool key 3; sleep 0.6
shot plain; scene plain
n=$(press l lamp); echo "L: $n pixels changed"
[ "$n" -gt 2000 ] || fail "L did not light the scene ($n pixels)"
grep -q "point light at" "$out/viewer.log" || fail "L did not report the point light"
n=$(press k unlit); echo "K: $n pixels differ from before L"
[ "$n" -lt 20 ] || fail "K did not take the point light away ($n pixels)"
grep -q "point light removed" "$out/viewer.log" || fail "K did not report the removal"
n=$(press g glossy); echo "G: $n pixels changed"
[ "$n" -gt 500 ] || fail "G did not add highlights ($n pixels)"
n=$(press g matte); echo "G again: $n pixels differ from before G"
[ "$n" -lt 20 ] || fail "G again did not take the highlights away ($n pixels)"

# P saves under the next free name, never over an earlier file.
xdotool key p; sleep 0.5; xdotool key p; sleep 0.5
[ "$(cat "$shots/viewer-001.png")" = keep ] || fail "P overwrote viewer-001.png"
for n in 002 003; do
    [ "$(identify -format "%m %wx%h" "$shots/viewer-$n.png")" = "PNG 640x480" ] || fail "P did not save viewer-$n.png"
done

# R asks on the terminal; bad answers are reported and asked again; the window keeps running.
# While it asks, the frame-time lines pause.
printf 'v 0 0 0\nv 1 0 0\n' >"$out/points.obj"
xdotool key r; sleep 0.3
n0=$(grep -c "frame: render" "$out/viewer.log")
sleep 2.5
n1=$(grep -c "frame: render" "$out/viewer.log")
[ "$n0" = "$n1" ] || fail "frame-time lines went on during the prompt ($n0 -> $n1)"
printf '/no/such/model.obj\n%s\ncube\n300,0,0\n40,200,90\n1,2\n0,0,1.5\n' "$out/points.obj" >&3
sleep 1.2
grep -q "No such file" "$out/viewer.log" || fail "a bad path was not reported"
grep -q "no triangles in $out/points.obj" "$out/viewer.log" || fail "a file without triangles was not reported"
grep -q "give three numbers 0-255" "$out/viewer.log" || fail "a bad colour was not reported"
grep -q "added object 6" "$out/viewer.log" || fail "the object was not added"
sleep 1.5
n2=$(grep -c "frame: render" "$out/viewer.log")
[ "$n2" -gt "$n1" ] || fail "frame-time lines did not come back after the prompt"
xdotool key r; sleep 0.3
printf 'exit\n' >&3
sleep 0.5
grep -q "cancelled" "$out/viewer.log" || fail "exit did not cancel"
xdotool key BackSpace; sleep 0.4
grep -q "removed the last object, 5 left" "$out/viewer.log" || fail "Backspace did not remove the object"

xdotool key Escape
for _ in $(seq 50); do kill -0 $viewer 2>/dev/null || break; sleep 0.1; done
if kill -0 $viewer 2>/dev/null; then fail "Escape did not quit"; fi
wait $viewer || fail "the viewer exited with status $?"
viewer=
grep -q "frame: render" "$out/viewer.log" || fail "no render time printed"
echo "viewer test passed"
