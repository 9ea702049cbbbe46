#!/bin/bash
# Open and Save As through the desktop's own file dialog, in the real window under Xvfb: a
# stand-in zenity on the PATH (it logs its arguments and answers what OUTDIR/answer says), then
# the XDG desktop portal (sweep_fake_portal on a private session bus), then a zenity that fails
# (the in-app browser takes over), then none at all (said once), then the setting that forces the
# in-app browser.
# Usage: dialogs_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR   (SWEEP_FAKE_PORTAL: the fake portal)
# Prints "ok PART" for every part that behaved, then "done".
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, find_window, quit_viewer
unset DBUS_SESSION_BUS_ADDRESS
mkdir -p "$out/bin"
answer=$out/answer
cat >"$out/bin/zenity" <<EOF
#!/bin/sh
printf '%s\n' "\$@" >>"$out/zenity.args"
read -r line <"$answer"
[ "\$line" = cancel ] && exit 1
[ "\$line" = broken ] && { echo "cannot open display" >&2; exit 5; }
echo "\$line"
EOF
chmod +x "$out/bin/zenity"
other=$out/other.swp
printf 'circ other 12 2\n' >"$other"
export PATH="$out/bin:$PATH"

# ctrl KEYS: a shortcut once the window has the focus.
ctrl() {
  xdotool windowactivate --sync "$window" 2>/dev/null
  xdotool key --window "$window" "$1"
}

# Zenity: Open, Save As, and a cancelled Open.
SWEEP_FILE_CHOOSER=auto start_viewer zenity
wait_for '^selected ' 30 || fail "the viewer did not start"
find_window
echo "$other" >"$answer"
ctrl ctrl+o
wait_for '^dialog zenity$' 10 || fail "Ctrl+O did not ask zenity"
wait_for "^status opened $other\$" 10 || fail "the file zenity chose was not opened"
grep -q -- "--filename=$out/" "$out/zenity.args" || fail "zenity did not start in the file's folder"
echo "$out/saved.swp" >"$answer"
ctrl ctrl+shift+s
wait_for "^saved $out/saved.swp\$" 10 || fail "Save As did not save where zenity said"
grep -q -- "--save" "$out/zenity.args" || fail "Save As did not ask zenity's save dialog"
grep -q -- "--filename=$other" "$out/zenity.args" || fail "Save As did not suggest the current file"
cmp -s "$other" "$out/saved.swp" || fail "the saved file is not the document"
echo cancel >"$answer"
ctrl ctrl+o
wait_for '^dialog cancelled$' 10 || fail "a cancelled dialog was not seen"
quit_viewer "after the zenity dialogs"
echo "ok zenity"

# The portal, preferred over zenity when the session bus has it.
bus_out=$out/bus
dbus-daemon --session --nofork --print-address=1 >"$bus_out" 2>/dev/null &
bus_pid=$!
for _ in $(seq 100); do [ -s "$bus_out" ] && break; sleep 0.05; done
export DBUS_SESSION_BUS_ADDRESS=$(head -n 1 "$bus_out")
echo "$file" >"$answer"
"$SWEEP_FAKE_PORTAL" "$answer" "$out/portal.log" >"$out/portal.out" 2>&1 &
portal_pid=$!
for _ in $(seq 100); do grep -q ready "$out/portal.out" 2>/dev/null && break; sleep 0.05; done
SWEEP_FILE_CHOOSER=auto start_viewer portal
wait_for '^selected ' 30 || fail "the viewer did not start"
find_window
: >"$out/zenity.args"
ctrl ctrl+o
wait_for '^dialog the desktop portal$' 10 || fail "Ctrl+O did not ask the portal"
wait_for "^status opened $file\$" 10 || fail "the file the portal chose was not opened"
[ -s "$out/zenity.args" ] && fail "zenity was asked although the portal answers"
# The viewer says it asked before the portal has logged the call (and the "status opened" above
# may be the start's own line): wait for the portal's log, up to 10 s, as for the viewer's lines.
for _ in $(seq 200); do grep -q '^OpenFile Open a file$' "$out/portal.log" 2>/dev/null && break; sleep 0.05; done
grep -q '^OpenFile Open a file$' "$out/portal.log" || fail "the portal was not asked to open a file"
quit_viewer "after the portal dialog"
kill "$portal_pid" "$bus_pid" 2>/dev/null
unset DBUS_SESSION_BUS_ADDRESS
echo "ok portal"

# A dialog that fails: the message, and the in-app browser instead.
echo broken >"$answer"
SWEEP_FILE_CHOOSER=auto start_viewer broken
wait_for '^selected ' 30 || fail "the viewer did not start"
find_window
ctrl ctrl+o
wait_for '^dialog failed: zenity exited with status 5: cannot open display$' 10 || fail "the failure was not said"
wait_for "^error zenity exited with status 5: cannot open display; using Sweep's own file browser\$" 10 ||
  fail "the failure was not shown"
xdotool key Escape  # closes the in-app browser
sleep 0.3
quit_viewer "after a failed dialog"
echo "ok failure"

# The desktop's dialog asked for where there is none (no zenity, kdialog or portal): the status
# says which dialog opened and why, once.
if ! PATH="${PATH#"$out/bin:"}" command -v zenity >/dev/null && ! command -v kdialog >/dev/null; then
  PATH="${PATH#"$out/bin:"}" SWEEP_FILE_CHOOSER=auto start_viewer none
  wait_for '^selected ' 30 || fail "the viewer did not start"
  find_window
  ctrl ctrl+o
  said="^status no desktop file dialog here (no desktop portal, zenity or kdialog): Sweep's own file browser opened\$"
  wait_for "$said" 10 || fail "the fallback to the in-app browser was not said"
  xdotool key Escape  # closes the in-app browser
  sleep 0.3
  ctrl ctrl+o
  sleep 1
  [ "$(grep -c "$said" "$log")" = 1 ] || fail "the fallback was said more than once"
  xdotool key Escape
  sleep 0.3
  quit_viewer "without a desktop dialog"
  echo "ok none"
fi

# The setting: always the in-app browser.
mkdir -p "$XDG_CONFIG_HOME/sweep"
echo "file-chooser in-app" >"$XDG_CONFIG_HOME/sweep/settings.txt"
: >"$out/zenity.args"
echo "$other" >"$answer"
SWEEP_FILE_CHOOSER= start_viewer setting
wait_for '^selected ' 30 || fail "the viewer did not start"
find_window
ctrl ctrl+o
sleep 1
grep -q '^dialog ' "$log" && fail "the desktop's dialog was used although the setting says in-app"
[ -s "$out/zenity.args" ] && fail "zenity was asked although the setting says in-app"
xdotool key Escape
sleep 0.3
quit_viewer "with the in-app setting"
echo "ok setting"
echo done
