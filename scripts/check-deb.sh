#!/usr/bin/env bash
# Checks build/sweep_*.deb with lintian, then installs it on a fresh Debian 12 and uses it: a
# measurement, not a ctest test (it downloads a Debian base system and the package's
# dependencies, a few minutes).
#   bash scripts/check-deb.sh [--lintian-only] [PACKAGE.deb]
# lintian (apt-get install lintian) runs first, on the host: any error (E:) or warning (W:) fails
# the check; --lintian-only stops there. Then, with a docker daemon, it uses the debian:12 image;
# otherwise, as root, a debootstrap'ed bookworm chroot in a temporary folder (apt-get install
# debootstrap). In the fresh system:
# `apt install ./sweep_*.deb`, then `sweep --version`, `sweep info`, `sweep render` (through the
# installed viewer module and OSMesa) and the thumbnailer's Exec line; prints each step's time.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
lintian_only=0
if [ "${1:-}" = --lintian-only ]; then lintian_only=1; shift; fi
deb="$(realpath "${1:-$(ls "$root"/build/sweep_*.deb | tail -1)}")"
[ -f "$deb" ] || { echo "check-deb: no package (cd build && cpack -G DEB)" >&2; exit 1; }

command -v lintian >/dev/null || { echo "check-deb: needs lintian (apt-get install lintian)" >&2; exit 1; }
t0=$(date +%s)
# Shows the info tags too (I:); only errors and warnings fail.
lintian --display-info --fail-on error,warning "$deb" || { echo "check-deb: lintian: errors or warnings" >&2; exit 1; }
echo "check-deb: lintian $(lintian --version | sed 's/^Lintian v//'): no errors or warnings ($(( $(date +%s) - t0 )) s)"
[ "$lintian_only" -eq 0 ] || exit 0

# What runs inside the fresh system, with the package and a model in /check.
inside='set -eu
export DEBIAN_FRONTEND=noninteractive
t0=$(date +%s)
apt-get update -qq
apt-get install -y -qq --no-install-recommends ./check/'"$(basename "$deb")"' >/check/apt.log
echo "check-deb: apt install took $(( $(date +%s) - t0 )) s; $(dpkg-query -W -f "\${Package} \${Version}" sweep)"
sweep --version
sweep info /check/wineglass.swp
sweep render /check/wineglass.swp -o /check/render.png --size 160x120
exec_line=$(sed -n "s/^Exec=//p" /usr/share/thumbnailers/sweep.thumbnailer)
exec_line=${exec_line//%i//check/wineglass.swp}; exec_line=${exec_line//%o//check/thumb.png}; exec_line=${exec_line//%s/128}
$exec_line
ls -l /usr/lib/*/sweep /usr/lib/sweep 2>/dev/null || true
echo "check-deb: ok"'

work="$(mktemp -d /tmp/sweep-check-deb.XXXXXX)"
mkdir -p "$work/check"
cp "$deb" "$root/swp/wineglass.swp" "$work/check/"
if docker info >/dev/null 2>&1; then
  echo "check-deb: docker debian:12"
  docker run --rm -v "$work/check:/check" -w / debian:12 bash -c "$inside"
  exit
fi
[ "$(id -u)" -eq 0 ] && command -v debootstrap >/dev/null ||
  { echo "check-deb: needs a docker daemon, or root and debootstrap" >&2; exit 1; }
chroot_dir="$work/bookworm"
t0=$(date +%s)
debootstrap --variant=minbase bookworm "$chroot_dir" http://deb.debian.org/debian >"$work/debootstrap.log"
echo "check-deb: debootstrap bookworm took $(( $(date +%s) - t0 )) s ($work)"
mv "$work/check" "$chroot_dir/check"
mount -t proc proc "$chroot_dir/proc"
trap 'umount "$chroot_dir/proc"' EXIT
chroot "$chroot_dir" /bin/bash -c "cd / && $inside"
cp "$chroot_dir/check/"*.png "$work/" 2>/dev/null || true
echo "check-deb: pictures in $work"
