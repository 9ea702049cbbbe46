#!/usr/bin/env bash
# library_check.sh CHECK BUILD SOURCE OUT CXX: the installed C++ library (cmake/library.cmake,
# issue 57) as a program outside this project uses it (tests/install/CMakeLists.txt):
#   examples  installs BUILD into a fresh prefix (and moves it: the package is relocatable),
#             builds SOURCE/examples/ as a project of its own against it (find_package(Sweep),
#             warnings as errors), runs each example on swp/wineglass.swp and checks what it
#             prints against the installed `sweep` (info, frames) and the files it writes; builds
#             load_mesh again with pkg-config alone
#   docs      docs/library.md as written: its ```sh blocks in order, as one script run from a
#             folder that looks like the repository's root (build/, examples/, swp/) with a HOME
#             of its own (so `--prefix ~/.local` installs under OUT); then its ```cmake block and
#             every ```cpp block holding `int main`, built against that install and run in a
#             folder with a copy of wineglass.swp; a ```text block that comes next after a
#             program (no other fence between) is what the program must print, exactly
# CXX is the compiler the build uses. On 2 cores examples takes about 8 s and docs about 18 s
# (27 s for both side by side), most of it compiling.
set -euo pipefail
check=$1 build=$2 source=$3 out=$4 cxx=$5
fail() { echo "library_check $check: $*" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out"
swp=$source/swp
examples="load_mesh curve_frames edit_and_save render_png snapshot_check"

# run STATUS PROGRAM ARGS...: runs PROGRAM, its stdout in $out/stdout and stderr in $out/stderr,
# and fails unless it exits with STATUS.
run() {
  local expected=$1 status=0
  shift
  "$@" >"$out/stdout" 2>"$out/stderr" || status=$?
  [ "$status" = "$expected" ] ||
    fail "'$*' exited $status, not $expected; stdout: $(cat "$out/stdout"); stderr: $(cat "$out/stderr")"
}
# expect_stdout TEXT / expect_stderr TEXT: the last run printed exactly TEXT there.
expect_stdout() { [ "$(cat "$out/stdout")" = "$1" ] || fail "printed '$(cat "$out/stdout")', not '$1'"; }
expect_stderr() { [ "$(cat "$out/stderr")" = "$1" ] || fail "said '$(cat "$out/stderr")' on stderr, not '$1'"; }

# The libsweep PROGRAM loads is the one in PREFIX.
uses_prefix_library() {
  local libraries
  libraries=$(ldd "$1")
  grep -q "libsweep.so.0 => $2/lib/libsweep.so.0 " <<<"$libraries" || fail "$1 does not load $2's libsweep: $libraries"
}

check_examples() {
  local prefix=$out/prefix ex=$out/build-examples moved=$out/moved/wineglass.swp refs=$out/references info
  cmake --install "$build" --prefix "$out/staged" >/dev/null
  mv "$out/staged" "$prefix"
  [ -f "$prefix/lib/cmake/Sweep/SweepConfig.cmake" ] && [ -f "$prefix/include/sweep/version.hpp" ] ||
    fail "the prefix has no CMake package or no version.hpp"

  cmake -S "$source/examples" -B "$ex" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_COMPILE_WARNING_AS_ERROR=ON -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$out/configure.log" 2>&1 ||
    fail "configuring examples/: $(cat "$out/configure.log")"
  [ "$(sed -n 's/^Sweep_DIR:PATH=//p' "$ex/CMakeCache.txt")" = "$prefix/lib/cmake/Sweep" ] ||
    fail "find_package(Sweep) found $(sed -n 's/^Sweep_DIR:PATH=//p' "$ex/CMakeCache.txt"), not the prefix's"
  cmake --build "$ex" -j 2 >"$out/build.log" 2>&1 || fail "building examples/: $(cat "$out/build.log")"
  ! grep -i "warning" "$out/build.log" || fail "examples/ builds with warnings"
  for e in $examples; do
    [ -x "$ex/$e" ] || fail "no $e built"
    uses_prefix_library "$ex/$e" "$prefix"
  done

  # load_mesh: the counts `sweep info` gives (the installed program, another way in).
  info=$("$prefix/bin/sweep" info "$swp/wineglass.swp")
  local vertices triangles samples
  vertices=$(sed -n 's/^ *srev wineglass .*: \([0-9]*\) vertices, [0-9]* triangles$/\1/p' <<<"$info")
  triangles=$(sed -n 's/^ *srev wineglass .*: [0-9]* vertices, \([0-9]*\) triangles$/\1/p' <<<"$info")
  samples=$(sed -n 's/^ *bsp2 profile .*, \([0-9]*\) samples$/\1/p' <<<"$info")
  [ "${vertices:-0}" -gt 0 ] && [ "${triangles:-0}" -gt 0 ] && [ "${samples:-0}" -gt 0 ] ||
    fail "no counts in sweep info: $info"
  run 0 "$ex/load_mesh" "$swp/wineglass.swp"
  expect_stdout "surface wineglass (srev): $vertices vertices, $triangles triangles
curve profile (bsp2): $samples samples"
  expect_stderr ""
  printf 'bsp2 profile 8 4\n[0 0]\n[1 x]\n[2 0]\n[3 1]\n' >"$out/bad.swp"
  run 1 "$ex/load_mesh" "$out/bad.swp"
  expect_stdout ""
  expect_stderr "error: $out/bad.swp:3:4: expected a number (y of point 2 of 4), found 'x'"

  # curve_frames: 5 parameters over 0..23 (26 points of a cubic B-spline), each a sample of
  # `sweep frames` (8 steps a piece): V and T agree with its CSV.
  run 0 "$ex/curve_frames" "$swp/wineglass.swp" profile 5
  [ "$(awk '{print $2}' "$out/stdout" | tr '\n' ' ')" = "0.000000 5.750000 11.500000 17.250000 23.000000 " ] ||
    fail "curve_frames parameters: $(cat "$out/stdout")"
  "$prefix/bin/sweep" frames "$swp/wineglass.swp" profile >"$out/frames.csv"
  # Each line: t T  V (x, y, z)  T (x, y, z); tr drops the punctuation.
  tr -d '(),' <"$out/stdout" | awk -F, -v csv="$out/frames.csv" '
    BEGIN { while ((getline line < csv) > 0) { n = split(line, f, ","); if (f[1] ~ /^[0-9.]+$/) row[f[1] + 0] = line } }
    {
      split($0, w, " ")  # t T V x y z T x y z
      if (!((w[2] + 0) in row)) { print "no sample at t " w[2]; bad = 1; next }
      split(row[w[2] + 0], f, ",")
      for (i = 0; i < 3; ++i) {
        if ((w[4 + i] - f[2 + i]) ^ 2 > 1e-10 || (w[8 + i] - f[5 + i]) ^ 2 > 1e-10) { print "t " w[2] " differs: " $0; bad = 1 }
      }
      length2 = w[8] ^ 2 + w[9] ^ 2 + w[10] ^ 2
      if ((length2 - 1) ^ 2 > 1e-8) { print "T is not a unit vector at t " w[2]; bad = 1 }
      ++lines
    }
    END { if (lines != 5) { print lines " lines"; bad = 1 } exit bad }' >"$out/frames-check.txt" ||
    fail "curve_frames disagrees with sweep frames: $(cat "$out/frames-check.txt")"
  run 1 "$ex/curve_frames" "$swp/wineglass.swp" wineglass
  expect_stderr "error: 'wineglass' in $swp/wineglass.swp is not a curve"

  # edit_and_save: the saved file is the input with one line changed, the moved point's.
  mkdir -p "$out/moved" "$out/moved-7"
  run 0 "$ex/edit_and_save" "$swp/wineglass.swp" "$moved"
  expect_stdout "moved profile point 6 from (-1.164785, 1.105511) to (-1.064785, 1.105511)
saved $moved"
  [ "$(diff "$swp/wineglass.swp" "$moved" || true)" = "9c9
< [-1.164785 1.105511]
---
> [-1.064785 1.105511]" ] || fail "the saved file differs otherwise: $(diff "$swp/wineglass.swp" "$moved")"
  run 0 "$ex/edit_and_save" "$swp/wineglass.swp" "$out/moved-7/wineglass.swp" profile 7 0 0.05
  [ "$(diff "$swp/wineglass.swp" "$out/moved-7/wineglass.swp" || true)" = "10c10
< [-0.991667 2.328629]
---
> [-0.991667 2.378629]" ] || fail "moving point 7: $(diff "$swp/wineglass.swp" "$out/moved-7/wineglass.swp")"
  run 1 "$ex/edit_and_save" "$swp/wineglass.swp" "$out/not-written.swp" profile 99 1 1
  expect_stdout ""
  expect_stderr "error: point 99 is out of range: curve 'profile' has 26 points"
  [ ! -e "$out/not-written.swp" ] || fail "a failed edit wrote its output"

  # render_png: a PNG of the size asked for (its IHDR: the signature, then length, "IHDR",
  # width and height big-endian) that shows something.
  run 0 "$ex/render_png" "$swp/wineglass.swp" "$out/glass.png" 123 45
  expect_stdout "wrote $out/glass.png (123 x 45)"
  [ "$(od -An -tu1 -N24 "$out/glass.png" | tr -s ' \n' ' ')" = \
    " 137 80 78 71 13 10 26 10 0 0 0 13 73 72 68 82 0 0 0 123 0 0 0 45 " ] ||
    fail "not a 123x45 PNG: $(od -An -tu1 -N24 "$out/glass.png")"
  [ "$(identify -format '%k' "$out/glass.png")" -ge 16 ] || fail "the picture is (nearly) blank"
  run 1 "$ex/render_png" "$swp/wineglass.swp" "$out/zero.png" 0 45
  grep -Eqx "error: a picture is 1 to [0-9]+ pixels a side, not 0x45" "$out/stderr" || fail "0x45: $(cat "$out/stderr")"
  [ ! -e "$out/zero.png" ] || fail "a failed render wrote a file"

  # snapshot_check: new (exit 1), then pass (0); the moved glass fails (1) naming what changed.
  run 1 "$ex/snapshot_check" "$swp/wineglass.swp" "$refs"
  expect_stdout "new: new reference $refs/wineglass-smooth.png"
  [ -f "$refs/wineglass-smooth.png" ] && [ -f "$refs/wineglass-smooth.json" ] || fail "no reference written"
  run 0 "$ex/snapshot_check" "$swp/wineglass.swp" "$refs"
  expect_stdout "pass: identical"
  run 1 "$ex/snapshot_check" "$moved" "$refs"
  head -1 "$out/stdout" | grep -q '^FAIL: .* changed where the model changed (profile, wineglass)' ||
    fail "the moved glass: $(cat "$out/stdout")"
  [ "$(tail -n +2 "$out/stdout" | grep -cE '^  (profile|wineglass): [0-9]+ pixels changed')" -ge 1 ] &&
    [ "$(tail -n +2 "$out/stdout" | grep -cvE '^  (profile|wineglass): ')" = 0 ] ||
    fail "the moved glass's objects: $(cat "$out/stdout")"
  run 1 "$ex/snapshot_check" "$moved" "$refs" moved  # another name: another reference
  expect_stdout "new: new reference $refs/moved-smooth.png"
  run 1 "$ex/snapshot_check" "$out/missing.swp" "$refs"
  expect_stderr "error: $out/missing.swp: cannot open: No such file or directory"

  # pkg-config alone: the same load_mesh, built by hand.
  local pc_flags includedir
  export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
  includedir=$(pkg-config --variable=includedir sweep)
  [ "$(realpath "$includedir")" = "$prefix/include" ] || fail "sweep.pc's includedir is $includedir"
  pc_flags=$(pkg-config --cflags --libs sweep)
  # shellcheck disable=SC2086  # the flags are words
  (cd "$source/examples/load_mesh" && "$cxx" -std=c++20 main.cpp $pc_flags -o "$out/load_mesh_pc") \
    >"$out/pc-build.log" 2>&1 ||
    fail "pkg-config build: $(cat "$out/pc-build.log")"
  LD_LIBRARY_PATH=$prefix/lib uses_prefix_library "$out/load_mesh_pc" "$prefix"
  LD_LIBRARY_PATH=$prefix/lib run 0 "$out/load_mesh_pc" "$swp/wineglass.swp"
  expect_stdout "surface wineglass (srev): $vertices vertices, $triangles triangles
curve profile (bsp2): $samples samples"
}

# Every fenced block of docs/library.md into $out/blocks/NN.KIND (NN counts the blocks, two
# digits, so they sort in order), and a ```text block that comes next after one (no fence
# between) into NN.expected; other ```text blocks are dropped.
extract_blocks() {
  mkdir -p "$out/blocks"
  awk -v dir="$out/blocks" '
    /^```/ {
      if (open) { close(file); open = 0; last = kind != "text" ? number : ""; next }
      kind = substr($0, 4); number = sprintf("%02d", ++n); open = 1
      if (kind != "text") file = dir "/" number "." kind
      else if (last != "") file = dir "/" last ".expected"
      else file = "/dev/null"
      next
    }
    open { print > file }' "$source/docs/library.md"
}

check_docs() {
  local sandbox=$out/sandbox home=$out/sandbox/home programs=0 outputs=0 n block
  mkdir -p "$home"
  ln -s "$build" "$sandbox/build"
  ln -s "$source/examples" "$sandbox/examples"
  ln -s "$source/swp" "$sandbox/swp"
  extract_blocks
  cat "$out"/blocks/*.sh >"$out/shell-blocks.sh" 2>/dev/null || fail "docs/library.md has no sh block"
  (cd "$sandbox" && HOME=$home bash -euo pipefail "$out/shell-blocks.sh") >"$out/shell.log" 2>&1 ||
    fail "the doc's shell blocks: $(cat "$out/shell.log")"
  [ -f "$home/.local/lib/libsweep.so.0" ] || fail "the shell blocks installed nothing into ~/.local"
  [ "$(grep -c '^surface wineglass (srev): [1-9][0-9]* vertices' "$out/shell.log")" = 2 ] ||
    fail "the shell blocks did not run load_mesh twice: $(cat "$out/shell.log")"

  export PKG_CONFIG_PATH=$home/.local/lib/pkgconfig LD_LIBRARY_PATH=$home/.local/lib
  local flags first=""
  flags=$(pkg-config --cflags --libs sweep)
  # Every program, two compilers at a time.
  for block in "$out"/blocks/*.cpp; do
    grep -q 'int main' "$block" || continue
    basename "$block" .cpp
  done | xargs -P 2 -I{} sh -c "'$cxx' -std=c++20 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Werror \
      '$out/blocks/{}.cpp' $flags -o '$out/blocks/{}' >'$out/blocks/{}.log' 2>&1 || echo {}" >"$out/failed.txt"
  [ ! -s "$out/failed.txt" ] || fail "blocks that do not compile: $(for n in $(cat "$out/failed.txt"); do
      echo "block $n:"; cat "$out/blocks/$n.log"; done)"
  for block in "$out"/blocks/*.cpp; do
    grep -q 'int main' "$block" || continue
    n=$(basename "$block" .cpp)
    programs=$((programs + 1))
    [ -n "$first" ] || first=$n
    mkdir -p "$out/run/$n"
    cp "$swp/wineglass.swp" "$out/run/$n/"
    cd "$out/run/$n"
    run 0 "$out/blocks/$n"
    cd "$out"
    if [ -f "$out/blocks/$n.expected" ]; then
      outputs=$((outputs + 1))
      diff "$out/blocks/$n.expected" "$out/stdout" >"$out/blocks/$n.diff" ||
        fail "block $n prints otherwise than the doc says: $(cat "$out/blocks/$n.diff")"
    fi
  done
  [ "$programs" -ge 5 ] && [ "$outputs" -ge 3 ] || fail "only $programs programs, $outputs with their output"

  # The ```cmake block builds the first program, which prints what the doc says.
  [ "$(ls "$out"/blocks/*.cmake | wc -l)" = 1 ] || fail "not one cmake block"
  mkdir -p "$out/hello"
  cp "$out"/blocks/*.cmake "$out/hello/CMakeLists.txt"
  cp "$out/blocks/$first.cpp" "$out/hello/main.cpp"
  cmake -S "$out/hello" -B "$out/hello/build" -DCMAKE_PREFIX_PATH="$home/.local" -DCMAKE_CXX_COMPILER="$cxx" \
    >"$out/hello.log" 2>&1 && cmake --build "$out/hello/build" >>"$out/hello.log" 2>&1 ||
    fail "the cmake block: $(cat "$out/hello.log")"
  (cd "$out/run/$first" && "$out/hello/build/hello" >"$out/hello.actual")
  diff "$out/blocks/$first.expected" "$out/hello.actual" || fail "the cmake block's program prints otherwise"
  echo "$programs programs, $outputs outputs compared"
}

"check_$check"
echo "library_check $check: ok"
