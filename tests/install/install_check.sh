#!/usr/bin/env bash
# install_check.sh CHECK BUILD SOURCE OUT: installs BUILD (cmake --install, prefix /usr) into
# OUT/root and checks one thing of the installed program (tests/install/CMakeLists.txt):
#   destdir      the installed sweep runs (info, --version) and renders through the installed
#                viewer module; the desktop entry passes desktop-file-validate
#   appstream    the AppStream metainfo passes `appstreamcli validate --no-net` and agrees with
#                the desktop entry, the MIME type, the version and the screenshot in assets/
#   thumbnailer  the installed .thumbnailer's Exec line, %i %o %s substituted, writes a PNG of
#                the requested size
#   man          the man page names every subcommand `sweep --help` lists
#   completion   bash completion offers the subcommands and a subcommand's options
#   mime         with the installed MIME type, a real SWP file named *.swp is application/x-sweep
#                and a vim swap file named x.swp is not; every SWP keyword has a magic rule
#   deb          cpack -G DEB: the file list (no tests, benchmarks or static libraries), the
#                Depends that dpkg-shlibdeps found, no maintainer scripts, the changelog's
#                version and maintainer, and lintian with no error or warning; the same for the
#                library's packages libsweep0, libsweep-dev and python3-sweep
set -euo pipefail
check=$1 build=$2 source=$3 out=$4
fail() { echo "install_check $check: $*" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out"
root=$out/root
DESTDIR=$root cmake --install "$build" --prefix /usr >/dev/null
sweep=$root/usr/bin/sweep
[ -x "$sweep" ] || fail "no $sweep"
share=$root/usr/share
# The application's id (cmake/install.cmake): the one metainfo file names it.
app_id=$(basename "$(echo "$share"/metainfo/*.metainfo.xml)" .metainfo.xml)
desktop=$share/applications/$app_id.desktop
version=$(sed -n 's/^project(Sweep VERSION \([0-9.]*\).*/\1/p' "$source/CMakeLists.txt")

check_destdir() {
  "$sweep" info "$source/swp/wineglass.swp" | grep -q "srev wineglass" || fail "sweep info"
  [ "$("$sweep" --version)" = "sweep $version" ] || fail "sweep --version: $("$sweep" --version)"
  # The build's module is not beside the installed binary: this render loads the installed one.
  [ ! -e "$root/usr/bin/libsweep_gui.so" ] || fail "the module is installed beside the binary"
  if [ -f "$build/libsweep_gui.so" ]; then
    "$sweep" render "$source/swp/wineglass.swp" -o "$out/render.png" --size 64x48 >/dev/null
    [ "$(identify -format '%wx%h' "$out/render.png")" = 64x48 ] || fail "sweep render"
  fi
  desktop-file-validate "$desktop" || fail "desktop-file-validate"
  grep -qx 'Exec=sweep view %f' "$desktop" || fail "Exec of the desktop entry"
  [ -f "$share/icons/hicolor/scalable/apps/sweep.svg" ] || fail "no icon"
}

# The text of the metainfo's elements named $1 (one per line).
metainfo_values() { sed -n "s|.*<$1[^>]*>\([^<]*\)</$1>.*|\1|p" "$share/metainfo/$app_id.metainfo.xml"; }

check_appstream() {
  local metainfo=$share/metainfo/$app_id.metainfo.xml image
  [ "$(ls "$share/metainfo")" = "$app_id.metainfo.xml" ] || fail "metainfo files: $(ls "$share/metainfo")"
  appstreamcli validate --no-net --pedantic "$metainfo" || fail "appstreamcli validate"
  [ "$(metainfo_values id)" = "$app_id" ] || fail "the component id is not $app_id"
  [[ "$app_id" == *.*.* ]] || fail "the id $app_id is not reverse DNS"
  # Software centres find the application through its desktop entry: the launchable.
  [ "$(metainfo_values launchable)" = "$app_id.desktop" ] || fail "launchable: $(metainfo_values launchable)"
  [ -f "$desktop" ] || fail "no desktop entry $app_id.desktop"
  [ "$(metainfo_values mediatype)" = application/x-sweep ] || fail "mediatype: $(metainfo_values mediatype)"
  grep -qx 'MimeType=application/x-sweep;' "$desktop" || fail "the desktop entry opens no application/x-sweep"
  grep -q '<mime-type type="application/x-sweep">' "$share/mime/packages/sweep.xml" || fail "no such MIME type"
  grep -q '<content_rating type="oars-1.1"' "$metainfo" || fail "no content rating"
  [ "$(metainfo_values binary)" = sweep ] || fail "provides binary: $(metainfo_values binary)"
  [ "$(sed -n 's/.*<release version="\([^"]*\)".*/\1/p' "$metainfo" | head -1)" = "$version" ] ||
    fail "the newest release is not $version"
  # The screenshot is a picture of this repository, at the address it will have once published.
  image=$(metainfo_values image)
  [[ "$image" == https://*/assets/*.png ]] || fail "screenshot: $image"
  [ -f "$source/assets/${image##*/assets/}" ] || fail "the screenshot $image is not in assets/"
}

check_thumbnailer() {
  local exec size=96
  exec=$(sed -n 's/^Exec=//p' "$share/thumbnailers/sweep.thumbnailer")
  [[ "$exec" == sweep\ * ]] || fail "Exec=$exec"
  exec=${exec//%i/$source/swp/wineglass.swp}
  exec=${exec//%o/$out/thumb.png}
  exec=${exec//%s/$size}
  # Word splitting as the file manager does (no quoting in our Exec line).
  (cd "$out" && PATH=$root/usr/bin:$PATH && $exec >/dev/null) || fail "running: $exec"
  [ "$(identify -format '%m %wx%h' "$out/thumb.png")" = "PNG ${size}x${size}" ] ||
    fail "thumbnail is $(identify -format '%m %wx%h' "$out/thumb.png")"
}

# The subcommands `sweep --help` lists under "Subcommands:".
subcommands() { "$sweep" --help | sed -n '/^Subcommands:/,$ s/^  \([a-z][a-z-]*\) .*/\1/p'; }

check_man() {
  local page commands name
  page=$(zcat "$root/usr/share/man/man1/sweep.1.gz")
  commands=$(subcommands)
  [ "$(echo "$commands" | wc -l)" -ge 4 ] || fail "too few subcommands: $commands"  # 6 with the viewer
  for name in $commands; do
    grep -qx "$name" <<<"$page" || fail "the man page lists no command '$name'"
    grep -q "^\.SS \"sweep $name\"" <<<"$page" || fail "the man page has no section 'sweep $name'"
  done
  grep -q 'sweep export.*--format' <<<"$(echo "$page" | tr '\n' ' ' | sed 's/\\-/-/g')" || fail "no export options"
}

check_completion() {
  local got
  # shellcheck disable=SC1091
  source "$share/bash-completion/completions/sweep"
  PATH=$root/usr/bin:$PATH
  COMP_WORDS=(sweep "")
  COMP_CWORD=1
  _sweep
  [ "$(printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' ')" = "$(subcommands | sort | tr '\n' ' ')" ] ||
    fail "subcommands: ${COMPREPLY[*]}"
  COMP_WORDS=(sweep info x.swp --to)
  COMP_CWORD=3
  _sweep
  [ "${COMPREPLY[*]}" = "--tolerance" ] || fail "info --to: ${COMPREPLY[*]}"
  COMP_WORDS=(sweep export x.swp --f)
  COMP_CWORD=3
  _sweep
  got=$(printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' ')
  [ "$got" = "--format --frames " ] || fail "export --f: $got"
  COMP_WORDS=(sweep import vase.svg vase.swp --re)
  COMP_CWORD=4
  _sweep
  [ "${COMPREPLY[*]}" = "--revolve" ] || fail "import --re: ${COMPREPLY[*]}"
  # snapshot's --update{all,missing} is offered as --update (a build without the GUI module,
  # the sanitizer build, has no snapshot subcommand).
  subcommands | grep -qx snapshot || return 0
  COMP_WORDS=(sweep snapshot models --upd)
  COMP_CWORD=3
  _sweep
  [ "${COMPREPLY[*]}" = "--update" ] || fail "snapshot --upd: ${COMPREPLY[*]}"
}

# The content type gio gives FILE with only the installed MIME type added to the system's.
content_type() {
  XDG_DATA_HOME=$out/xdg XDG_DATA_DIRS=/usr/share gio info -a standard::content-type "$1" |
    sed -n 's/^ *standard::content-type: //p'
}

check_mime() {
  local xml=$share/mime/packages/sweep.xml keyword
  mkdir -p "$out/xdg/mime/packages" "$out/files"
  cp "$xml" "$out/xdg/mime/packages/"
  update-mime-database "$out/xdg/mime" 2>/dev/null
  cp "$source/swp/wineglass.swp" "$source/swp/knots.swp" "$out/files/"
  printf '\n\nmaterial m color 1 0 0\n' >"$out/files/blank-lines.swp"
  # A vim swap file: "b0VIM", the version, binary fields, the edited file's name, zero padding.
  { printf 'b0VIM 9.0\0\0\0\0\x10\0\0\x9a\x01\0\0root\0'; head -c 100 /dev/zero; printf '/home/u/wineglass.swp\0';
    head -c 4000 /dev/zero; } >"$out/files/x.swp"
  for f in wineglass.swp knots.swp blank-lines.swp; do
    [ "$(content_type "$out/files/$f")" = application/x-sweep ] || fail "$f is $(content_type "$out/files/$f")"
  done
  [ "$(content_type "$out/files/x.swp")" != application/x-sweep ] || fail "a vim swap file is application/x-sweep"
  # Every keyword of src/model/kinds/kind_*.hpp starts a rule.
  for keyword in $(grep -ho '\.keyword = [^,]*' "$source"/src/model/kinds/kind_*.hpp | grep -o '"[a-z0-9]*"' | tr -d '"'); do
    grep -q "offset=\"0\" value=\"$keyword \"" "$xml" || fail "no magic rule for '$keyword'"
  done
}

check_deb() {
  local deb list depends
  (cd "$out" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$out/cpack" >/dev/null)
  deb=$(echo "$out"/cpack/sweep_*.deb)
  [ -f "$deb" ] || fail "no package in $out/cpack"
  list=$(dpkg-deb -c "$deb" | awk '{print $6}')
  for f in ./usr/bin/sweep ./usr/share/applications/$app_id.desktop ./usr/share/mime/packages/sweep.xml \
           ./usr/share/metainfo/$app_id.metainfo.xml ./usr/share/man/man1/sweep.1.gz \
           ./usr/share/bash-completion/completions/sweep ./usr/share/icons/hicolor/scalable/apps/sweep.svg \
           ./usr/share/doc/sweep/copyright ./usr/share/doc/sweep/changelog.gz; do
    grep -qx "$f" <<<"$list" || fail "the package has no $f"
  done
  ! grep -E '\.a$|test|bench|/include/' <<<"$list" || fail "the package holds tests, benchmarks or static libraries"
  [ "$(dpkg-deb -f "$deb" Section)" = graphics ] || fail "Section"
  # The changelog (packaging/changelog, gzip -9n) is of this version, signed by the maintainer.
  zcat "$root/usr/share/doc/sweep/changelog.gz" >"$out/changelog"
  cmp -s "$out/changelog" "$source/packaging/changelog" || fail "changelog.gz is not packaging/changelog"
  [ "$(dpkg-parsechangelog -l "$out/changelog" -S Version)" = "$(dpkg-deb -f "$deb" Version)" ] ||
    fail "the changelog is not of version $(dpkg-deb -f "$deb" Version)"
  [ "$(dpkg-parsechangelog -l "$out/changelog" -S Maintainer)" = "$(dpkg-deb -f "$deb" Maintainer)" ] ||
    fail "Maintainer $(dpkg-deb -f "$deb" Maintainer) did not sign the changelog"
  [[ "$(dpkg-deb -f "$deb" Maintainer)" == *\ \<*@*\> ]] || fail "Maintainer has no e-mail address"
  # The caches are refreshed by triggers and the viewer module is private: no scripts, no ldconfig.
  ! dpkg-deb -I "$deb" | grep -E ' (pre|post)(inst|rm) ' || fail "the package has maintainer scripts"
  lintian --fail-on error,warning "$deb" >"$out/lintian.txt" 2>&1 || fail "lintian: $(cat "$out/lintian.txt")"
  depends=$(dpkg-deb -f "$deb" Depends)
  for package in libc6 libstdc++6 libosdcpu; do
    grep -q "$package" <<<"$depends" || fail "Depends lacks $package: $depends"
  done
  if [ -f "$build/libsweep_gui.so" ]; then
    grep -q ./usr/lib/.*sweep/libsweep_gui.so <<<"$list" || fail "the package has no viewer module"
    for package in libglfw3 libosmesa6; do
      grep -q "$package" <<<"$depends" || fail "Depends lacks $package: $depends"
    done
    check_library_debs
  fi
}

# The library's packages (cmake/deb_components.cmake): each holds its part, depends as Debian
# expects, has its copyright file, and passes lintian with no error or warning.
check_library_debs() {
  local package file deb
  local -A holds=(
    [libsweep0]="./usr/lib/libsweep.so.0.2.0 ./usr/lib/libsweep.so.0"
    [libsweep-dev]="./usr/lib/libsweep.so ./usr/include/sweep/sweep.hpp ./usr/include/sweep/version.hpp
                    ./usr/lib/cmake/Sweep/SweepConfig.cmake ./usr/lib/pkgconfig/sweep.pc"
    [python3-sweep]="./usr/lib/python3/dist-packages/sweep/__init__.py ./usr/lib/python3/dist-packages/sweep/_sweep.pyi
                     ./usr/lib/python3/dist-packages/sweep/pytest_plugin.py")
  for package in "${!holds[@]}"; do
    deb=$(echo "$out"/cpack/${package}_*.deb)
    [ -f "$deb" ] || fail "no $package package in $out/cpack"
    list=$(dpkg-deb -c "$deb" | awk '{print $6}')
    for file in ${holds[$package]} ./usr/share/doc/$package/copyright; do
      grep -qx "$file" <<<"$list" || fail "$package has no $file"
    done
    lintian --fail-on error,warning "$deb" >"$out/lintian-$package.txt" 2>&1 ||
      fail "lintian $package: $(cat "$out/lintian-$package.txt")"
  done
  list=$(dpkg-deb -c "$out"/cpack/python3-sweep_*.deb)
  grep -q '/sweep/_sweep\.cpython-.*\.so$' <<<"$list" || fail "python3-sweep has no module"
  [ "$(dpkg-deb -f "$out"/cpack/libsweep-dev_*.deb Depends)" = "libsweep0 (= $version)" ] || fail "libsweep-dev Depends"
  grep -q "libsweep0 (= $version)" <<<"$(dpkg-deb -f "$out"/cpack/python3-sweep_*.deb Depends)" ||
    fail "python3-sweep does not depend on libsweep0"
  [ "$(dpkg-deb --ctrl-tarfile "$out"/cpack/libsweep0_*.deb | tar -xO ./triggers)" = "activate-noawait ldconfig" ] ||
    fail "libsweep0 has no ldconfig trigger"
}

"check_$check"
echo "install_check $check: ok"
