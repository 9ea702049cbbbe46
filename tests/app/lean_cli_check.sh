#!/usr/bin/env bash
# The `sweep` executable links no GL, OSMesa, LLVM, GLFW or ImGui, and the commands that draw
# nothing do not map them: only `sweep view` and `sweep render` open the sweep_gui module.
# Usage: lean_cli_check.sh SWEEP SWP_DIR OUT GUI(ON|OFF)
set -euo pipefail
sweep="$1"
swp="$2"
out="$3"
gui="$4"
rm -rf "$out"
mkdir -p "$out"
# The GL side; sweep_gui names the module itself (libsweep_gui.so).
drawing='lib(GL|GLX|GLdispatch|EGL|OSMesa|glfw|LLVM|gallium|imgui|sweep_gui)[.-]'

fail() {
  echo "lean_cli_check: $*" >&2
  exit 1
}

needed=$(readelf -d "$sweep" | grep NEEDED || true)
if grep -Eq "$drawing" <<<"$needed"; then fail "$sweep links a drawing library:"$'\n'"$needed"; fi

# The libraries a run of `sweep ARGS...` loads (DISPLAY unset: the plain form only exports).
loaded_by() {
  env --unset=DISPLAY --unset=WAYLAND_DISPLAY LD_DEBUG=libs "$sweep" "$@" 2>&1 >/dev/null || true
}

expect_lean() {
  local loaded
  loaded=$(loaded_by "$@")
  if grep -Eq "$drawing" <<<"$loaded"; then fail "sweep $* loads a drawing library:"$'\n'"$loaded"; fi
}

printf 'circ c 10 1\n' >"$out/one.swp"
printf 'o cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n' >"$out/quad.obj"
expect_lean info "$out/one.swp"
expect_lean info "$swp/tor.swp"
expect_lean --help
expect_lean view --help
expect_lean render --help
expect_lean render "$swp/tor.swp"  # the missing -o is reported without the module
expect_lean export "$swp/tor.swp" "$out/export"
expect_lean "$swp/tor.swp" "$out/plain"
expect_lean frames "$swp/tor.swp" sweep
expect_lean import "$out/quad.obj" "$out/quad.swp"
expect_lean no-such-command

[ "$gui" = ON ] || exit 0

# Positive control: `sweep render` does load the module and OSMesa, so the greps above would see them.
loaded=$(loaded_by render "$swp/tor.swp" -o "$out/tor.png" --size 64x48)
grep -q 'libsweep_gui\.so' <<<"$loaded" || fail "sweep render did not load libsweep_gui.so:"$'\n'"$loaded"
grep -q 'libOSMesa' <<<"$loaded" || fail "sweep render did not load libOSMesa:"$'\n'"$loaded"

# Without the module (a copy of the executable alone): one message and exit 1; help is unchanged.
mkdir -p "$out/alone"
cp "$sweep" "$out/alone/sweep"
alone=$(realpath "$out/alone")  # as /proc/self/exe names it
set +e
"$out/alone/sweep" render "$swp/tor.swp" -o "$out/alone/tor.png" >"$out/alone.out" 2>"$out/alone.err"
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "sweep render without the module: exit code $rc, expected 1"
[ ! -s "$out/alone.out" ] || fail "sweep render without the module printed on stdout: $(cat "$out/alone.out")"
[ "$(wc -l <"$out/alone.err")" -eq 1 ] || fail "expected one line on stderr, found: $(cat "$out/alone.err")"
grep -qF "sweep: cannot load the viewer ($alone/libsweep_gui.so): " "$out/alone.err" &&
  grep -q "No such file" "$out/alone.err" || fail "unexpected message: $(cat "$out/alone.err")"
[ ! -e "$out/alone/tor.png" ] || fail "sweep render without the module wrote a picture"
cmp <("$sweep" view --help) <("$out/alone/sweep" view --help) || fail "view --help differs without the module"
echo "lean_cli_check: ok"
