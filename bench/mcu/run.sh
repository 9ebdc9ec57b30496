#!/usr/bin/env bash
# Firmware presets of fixed3d on an emulated Cortex-M: library flash, static RAM, peak stack and
# exact instructions per frame (QEMU with -icount), and the hash of the frames drawn.
#
#   bench/mcu/run.sh setup       # once per machine: qemu-system-arm, binutils, rustup targets
#   bench/mcu/run.sh             # every preset on thumbv6m-none-eabi and thumbv7em-none-eabihf
#   PRESETS="full wire" TARGETS=thumbv6m-none-eabi bench/mcu/run.sh
#   BOARD=microbit bench/mcu/run.sh   # `wire` on the micro:bit model: a real Cortex-M0, 16 KiB RAM
#   PRESETS=knobs bench/mcu/run.sh    # the torus in every configuration of docs/accuracy.md
#   PRESETS=phong bench/mcu/run.sh    # Gouraud, highlights and a point light (their features)
#   NORMALS=per-frame bench/mcu/run.sh  # `full` and `bands` without their kept face normals
#   CHECK=1 bench/mcu/run.sh     # fail if a hash differs from bench/mcu/hashes.txt (the host's)
#                                # or a library's flash exceeds its budget in docs/footprint.md
#
# One line per preset and target:
#   preset=NAME target=TRIPLE lib_flash=BYTES static_ram=BYTES stack=BYTES instructions_per_frame=N hash=HEX
# lib_flash is the preset's flash (vectors + text + rodata + data) minus the harness alone
# (the `baseline` binary); static_ram is the preset's .data + .bss (its buffers included).
# Counts are guest instructions, identical across runs and hosts, not cycles.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"

if [[ "${1:-}" == setup ]]; then
    sudo=""
    [[ $(id -u) -eq 0 ]] || sudo=sudo
    if ! command -v qemu-system-arm >/dev/null || ! command -v size >/dev/null; then
        $sudo apt-get update -qq
        $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends qemu-system-arm binutils >/dev/null
    fi
    rustup target add thumbv6m-none-eabi thumbv7em-none-eabihf
    exit 0
fi

BOARD=${BOARD:-mps2}
if [[ $BOARD == microbit ]]; then
    TARGETS=${TARGETS:-thumbv6m-none-eabi}
    PRESETS=${PRESETS:-wire} # the others need more than 16 KiB of RAM
    features=(--no-default-features --features board-microbit)
else
    TARGETS=${TARGETS:-"thumbv6m-none-eabi thumbv7em-none-eabihf"}
    PRESETS=${PRESETS:-"wire flat full gouraud textured bands obj display boards"}
    features=()
    # NORMALS=per-frame: `full` and `bands` find each face's normal every frame instead of
    # keeping them.
    [[ ${NORMALS:-kept} == per-frame ]] && features+=(--features per-frame-normals)
fi
# `knobs` (every configuration of docs/accuracy.md) needs micromath, `phong` the library's
# point lights and highlights, and `variants` its wireframes; ask for each alone, as the other
# presets would then be built with them too.
[[ " $PRESETS " == *" knobs "* ]] && features+=(--features micromath)
[[ " $PRESETS " == *" phong "* ]] && features+=(--features phong)
[[ " $PRESETS " == *" variants "* ]] && features+=(--features wireframe)
OPT=${OPT:-s}
CHECK=${CHECK:-0}
QEMU_TIMEOUT=${QEMU_TIMEOUT:-600}
TARGET_DIR=${CARGO_TARGET_DIR:-$here/target}/$BOARD
RESULTS=${RESULTS:-$here/target/results.tsv}

for tool in qemu-system-arm size cargo; do
    command -v "$tool" >/dev/null || { echo "missing $tool: run '$0 setup'" >&2; exit 2; }
done

machine_for() {
    if [[ $BOARD == microbit ]]; then
        [[ $1 == thumbv6m-none-eabi ]] && { echo microbit; return; }
        echo "the micro:bit runs thumbv6m-none-eabi only" >&2
        return 1
    fi
    case "$1" in
        thumbv6m-none-eabi | thumbv7m-none-eabi) echo mps2-an385 ;; # Cortex-M3 runs v6-M code
        thumbv7em-none-eabi | thumbv7em-none-eabihf) echo mps2-an386 ;; # Cortex-M4F
        *) echo "unsupported target $1" >&2; return 1 ;;
    esac
}

sizes() { # elf -> "flash ram"
    size -A "$1" | awk '
        $1==".vector_table"{v=$2} $1==".text"{t=$2} $1==".rodata"{r=$2}
        $1==".data"{d=$2} $1==".bss"{b=$2} $1==".uninit"{u=$2}
        END{printf "%d %d\n", v+t+r+d, d+b+u}'
}

# Budgets: lines "budget PRESET TARGET BYTES" in docs/footprint.md.
budget_for() {
    { awk -v p="$1" -v t="$2" '$1=="budget" && $2==p && $3==t {print $4}' "$here/../../docs/footprint.md" 2>/dev/null || true; } | head -1
}

mkdir -p "$(dirname "$RESULTS")"
status=0
for target in $TARGETS; do
    machine=$(machine_for "$target")
    bins=(--bin baseline)
    for preset in $PRESETS; do bins+=(--bin "$preset"); done
    cargo build --quiet --profile "release-$OPT" --target "$target" --target-dir "$TARGET_DIR" "${bins[@]}" ${features[@]+"${features[@]}"}
    out=$TARGET_DIR/$target/release-$OPT
    read -r base_flash _ < <(sizes "$out/baseline")
    for preset in $PRESETS; do
        read -r flash ram < <(sizes "$out/$preset")
        lib_flash=$((flash - base_flash))
        log=$out/$preset.log
        if ! timeout "$QEMU_TIMEOUT" qemu-system-arm -M "$machine" -nographic \
            -semihosting-config enable=on,target=native -icount shift=10 \
            -kernel "$out/$preset" </dev/null >"$log" 2>&1; then
            echo "preset=$preset target=$target FAILED (see $log)" >&2
            tail -3 "$log" >&2
            status=1
            continue
        fi
        # One line per configuration (several for `knobs`, one for every other preset).
        while read -r line; do
            field() { sed -E "s/.* $1=([^ ]+).*/\1/" <<<"$line"; }
            name=$(sed -E 's/^preset=([^ ]+).*/\1/' <<<"$line")
            ipf=$(field instructions_per_frame)
            hash=$(field hash)
            stack=$(field stack)
            [[ $BOARD == mps2 ]] || target_label="$target@$BOARD"
            [[ $name == "$preset" ]] || name="$preset:$name"
            echo "preset=$name target=${target_label:-$target} lib_flash=$lib_flash static_ram=$ram stack=$stack instructions_per_frame=$ipf hash=$hash"
            printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$target" "$OPT" "$lib_flash" "$ram" "$stack" "$ipf" "$hash" >>"$RESULTS"
            if [[ $CHECK == 1 ]]; then
                key=$name
                [[ $BOARD == mps2 ]] || key="$name@$BOARD"
                expect=$(awk -v p="$key" '$1==p {print $2}' "$here/hashes.txt")
                # A preset's own line must have a hash in the file; a configuration of a
                # preset of several (`variants:...`) is checked where the file has one.
                if [[ ( $name == "$preset" || -n "$expect" ) && "$hash" != "$expect" ]]; then
                    echo "  hash $hash differs from the host's $expect" >&2
                    status=1
                fi
                budget=$(budget_for "$preset" "$target")
                if [[ -n "$budget" && $lib_flash -gt $budget ]]; then
                    echo "  library flash $lib_flash exceeds the budget of $budget bytes" >&2
                    status=1
                fi
            fi
        done < <(grep -E '^preset=' "$log")
    done
done
exit $status
