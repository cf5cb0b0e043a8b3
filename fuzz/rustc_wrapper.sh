#!/usr/bin/env bash
# The afl build's RUSTC_WRAPPER (`cargo xtask fuzz` sets it; docs/RELIABILITY.md "Fuzzing").
#
# `cargo afl build` puts afl's instrumentation into RUSTFLAGS, so cargo hands it to every crate it
# compiles: the SanitizerCoverage pass (`-C passes=sancov-module`, `-C llvm-args=-sanitizer-
# coverage-*`) and `-C codegen-units=1`. This wrapper keeps those flags only for the crates a fuzz
# target exercises (INSTRUMENTED below: the engine, the harness and the parsers the targets reach,
# chosen from `cargo tree --manifest-path fuzz/Cargo.toml -e normal`) and drops them for
# everything else (wgpu, naga, winit, egui, rapier, kira, gilrs, …), which then builds at the
# profile's optimisation and codegen units. Every other flag (`--cfg fuzzing`, debug assertions,
# overflow checks, afl's runtime object at link time) reaches every crate as before.
#
# Cargo does not fingerprint the wrapper, so xtask adds a hash of this file to RUSTFLAGS
# (`--cfg candela_afl_wrapper="…"`): editing the list rebuilds everything once.
set -euo pipefail

# Crate names as rustc sees them (`-` is `_`); a trailing `*` matches a prefix.
INSTRUMENTED=(
    candela fuzz_targets candela_fuzz
    # glTF / GLB and what it decodes inline (data URIs, percent-encoded URIs)
    gltf gltf_json serde_json serde serde_core base64 urlencoding percent_encoding
    # OBJ / MTL, tangents of loaded meshes
    tobj bevy_mikktspace
    # textures: PNG, JPEG, HDR, BMP, TGA, GIF, EXR
    image png fdeflate miniz_oxide flate2 zune_jpeg zune_core zune_inflate gif weezl exr half lebe
    # levels, settings, saves, bindings, scripts
    ron
    # sounds: WAV, Ogg Vorbis
    'symphonia*'
)

rustc=$1
shift

crate=""
prev=""
for arg in "$@"; do
    if [[ $prev == --crate-name ]]; then
        crate=$arg
        break
    fi
    prev=$arg
done

# Cargo's probes (`rustc -vV`, `--crate-name ___`) and the crates under test: unchanged.
if [[ -z $crate || $crate == ___ ]]; then
    exec "$rustc" "$@"
fi
for name in "${INSTRUMENTED[@]}"; do
    # shellcheck disable=SC2053 # the pattern match is the point
    if [[ $crate == $name ]]; then
        exec "$rustc" "$@"
    fi
done

# Is this `-C` value one of afl's instrumentation flags?
afl_only() {
    case $1 in
        passes=sancov* | llvm-args=-sanitizer-coverage* | codegen-units=1) return 0 ;;
        *) return 1 ;;
    esac
}

kept=()
while (($#)); do
    arg=$1
    shift
    if [[ $arg == -C ]] && (($#)); then
        if afl_only "$1"; then
            shift
            continue
        fi
        kept+=("$arg" "$1")
        shift
        continue
    fi
    if [[ $arg == -C* ]] && afl_only "${arg#-C}"; then
        continue
    fi
    kept+=("$arg")
done
exec "$rustc" "${kept[@]}"
