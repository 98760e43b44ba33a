#!/usr/bin/env bash
# Starts a headless LinuxCNC lathe for the tests and prints what to export:
#   eval "$(scripts/start-test-linuxcnc.sh DIR [PORT])"
#     -> TRUETURN_LINUXCNC_URL=linuxcnc://127.0.0.1:PORT  TRUETURN_LINUXCNC_DIR=DIR (part programs in DIR/nc)
# Stop it with: scripts/start-test-linuxcnc.sh --stop DIR   (by PID; then checks that no process, shared
# memory segment or lock file is left).
#
# The machine is a copy of the package's simulated lathe (sim/axis/lathe.ini, inch machine, X and Z) with:
#   [DISPLAY] DISPLAY = linuxcncrsh -p PORT (LinuxCNC's remote shell is the only user interface), no PYVCP,
#             no intro graphic, no tool-change position (M6 does not leave the part);
#   [HAL]     HALFILE = LIB:basic_sim.tcl -no_use_hal_manualtoolchange (no tool-change dialog), no HALUI,
#             no POSTGUI_HALFILE (they need a display);
#   [JOINT_n] HOME_SEARCH_VEL = 0, HOME_LATCH_VEL = 0 (homing sets the current position at once);
#   Z travel -15 .. 4 inch (a 325 mm shaft fits), 20 inch/s and 200 inch/s^2 (a part takes seconds);
#   the tool table gains T10001, the wear entry of tool 1 (X and Z zero).
# It runs as the nobody user for its real-time part (RTAPI_UID=65534; LinuxCNC refuses to run as root
# otherwise), with its FIFO in DIR/fifo (mode 1777) and a private HOME in DIR/home (LinuxCNC keeps
# $HOME/.tool.mmap there, which the standalone rs274 would otherwise share). Only one LinuxCNC may run on a
# machine: a running one is left alone and the start fails; the lock file (/tmp/linuxcnc.lock) and shared
# memory of one that was killed (its processes gone) are removed before the start.
set -euo pipefail

sample=/usr/share/doc/linuxcnc/examples/sample-configs/sim/axis
lock=/tmp/linuxcnc.lock
components="linuxcnc linuxcncsvr linuxcncrsh milltask io rtapi_app halcmd"

fail() { echo "start-test-linuxcnc: $*" >&2; exit 1; }

alive() { [[ -n "$1" ]] && kill -0 "$1" 2>/dev/null; }

# Whether PID still runs the component NAME (a PID of a component that ended may have been reused).
is_component() { [[ -n "$1" && "$(cat "/proc/$1/comm" 2>/dev/null)" == "$2" ]]; }

# The System V shared memory keys LinuxCNC uses: its NML buffers (linuxcnc.nml: 1001..1005), HAL
# (0x48414c32 "HAL2"), the uspace RTAPI (0x48484c34) and the motion module (0x64).
shm_left() {
    ipcs -m 2>/dev/null | awk '$1 ~ /^0x/ {print $1}' |
        grep -E '^0x(000003e[9a-d]|48414c32|48484c34|00000064)$' || true
}

# Processes of LinuxCNC's components still running (by name; only one LinuxCNC may run on a machine).
components_left() {
    local name
    for name in $components; do pgrep -x "$name" || true; done
}

# The shared memory and the lock file of a LinuxCNC that no longer runs.
remove_leftovers() {
    local key
    for key in $(shm_left); do ipcrm -M "$key" 2>/dev/null || true; done
    [[ -z "$(shm_left)" ]] || fail "LinuxCNC shared memory is still present: $(shm_left | tr '\n' ' ')"
    rm -f "$lock"
    [[ ! -e "$lock" ]] || fail "the lock file $lock could not be removed"
}

stop() {
    local dir pids pid waited
    dir=$(realpath -m "$1")
    [[ -f "$dir/linuxcnc.pid" ]] || { echo "start-test-linuxcnc: nothing started in $dir" >&2; return 0; }
    # "PID NAME" lines: the linuxcnc script and every component it started.
    pids=$(cat "$dir/linuxcnc.pid" "$dir/components.pid" 2>/dev/null || true)
    # Ending the display (linuxcncrsh) makes the linuxcnc script shut everything down in order.
    while read -r pid name; do
        if is_component "$pid" "$name"; then kill -TERM "$pid" || true; fi
    done < <(grep -w linuxcncrsh "$dir/components.pid" 2>/dev/null || true)
    read -r pid name <"$dir/linuxcnc.pid"
    for waited in $(seq 1 120); do
        is_component "$pid" "$name" || break
        sleep 0.25
    done
    # Whatever did not end by itself (a wedged task, a crashed display) is ended by its PID.
    local signal left
    for signal in TERM KILL; do
        left=""
        while read -r pid name; do
            if is_component "$pid" "$name"; then kill "-$signal" "$pid" 2>/dev/null || true; left+=" $pid ($name)"; fi
        done <<<"$pids"
        [[ -n "$left" ]] && sleep 1
    done
    left=""
    while read -r pid name; do
        if is_component "$pid" "$name"; then left+=" $pid ($name)"; fi
    done <<<"$pids"
    [[ -z "$left" ]] || fail "LinuxCNC processes still running after the stop:$left"
    left=$(components_left | tr '\n' ' ')
    [[ -z "${left// /}" ]] || fail "LinuxCNC processes still running after the stop: $left"
    # The linuxcnc script removes its segments and lock on a clean stop; after a forced one, remove ours.
    remove_leftovers
    rm -f "$dir/linuxcnc.pid" "$dir/components.pid"
}

if [[ "${1:-}" == "--stop" ]]; then
    stop "${2:?usage: start-test-linuxcnc.sh --stop DIR}"
    exit 0
fi

dir=$(realpath -m "${1:?usage: start-test-linuxcnc.sh DIR [PORT]}")
port="${2:-5007}"
command -v linuxcnc >/dev/null || fail "linuxcnc not found: install linuxcnc-uspace (scripts/install-deps.sh --with-test-tools)"
[[ -f "$sample/lathe.ini" ]] || fail "the package's lathe configuration $sample/lathe.ini is missing"
[[ "$port" =~ ^[0-9]+$ ]] && ((port > 0 && port < 65536)) || fail "the port must be 1 to 65535 (got $port)"
[[ -z "$(components_left)" ]] || fail "LinuxCNC processes already run on this machine: $(components_left | tr '\n' ' ')"
# No LinuxCNC runs: a lock file or shared memory left behind is from one that was killed (a machine stopped
# mid-run); LinuxCNC itself would refuse to start beside them.
if [[ -e "$lock" || -n "$(shm_left)" ]]; then
    echo "start-test-linuxcnc: removing what a LinuxCNC that no longer runs left behind (lock file, shared memory)" >&2
    remove_leftovers
fi
if (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; then fail "port $port is already in use"; fi

# A fresh configuration each start; the programs in nc/ stay (a restarted controller finds its programs again).
mkdir -p "$dir"
# The real-time part runs as nobody and reaches its FIFO through DIR (mktemp makes folders only their owner enters).
chmod 0755 "$dir"
find "$dir" -mindepth 1 -maxdepth 1 ! -name nc -exec rm -rf {} +
mkdir -p "$dir/config" "$dir/home" "$dir/fifo" "$dir/nc"
chmod 1777 "$dir/fifo"
chmod 0777 "$dir/nc"
cp "$sample/lathe.tbl" "$dir/config/lathe.tbl"
echo "T10001 P11 X+0.000000 Z+0.000000 ;wear of tool 1" >>"$dir/config/lathe.tbl"
touch "$dir/config/sim-lathe.var"

# The package's INI with the changes listed above, section by section.
awk -v port="$port" '
    /^[ \t]*\[/ { section = $0; gsub(/[][ \t]/, "", section); print; next }
    /^[ \t]*[A-Z_]+[ \t]*=/ {
        key = $0; sub(/^[ \t]*/, "", key); sub(/[ \t]*=.*/, "", key)
        if (section == "DISPLAY" && key == "DISPLAY") { print "DISPLAY = linuxcncrsh -p " port; next }
        if (section == "DISPLAY" && (key == "PYVCP" || key == "INTRO_GRAPHIC" || key == "INTRO_TIME")) next
        if (section == "HAL" && key == "HALFILE") { print "HALFILE = LIB:basic_sim.tcl -no_use_hal_manualtoolchange"; next }
        if (section == "HAL" && (key == "HALUI" || key == "POSTGUI_HALFILE")) next
        if (section == "EMCIO" && key == "TOOL_CHANGE_POSITION") next
        if (key == "HOME_SEARCH_VEL" || key == "HOME_LATCH_VEL") { print key " = 0"; next }
        if ((section == "AXIS_Z" || section == "JOINT_1") && key == "MIN_LIMIT") { print "MIN_LIMIT = -15.0"; next }
        if ((section == "AXIS_Z" || section == "JOINT_1") && key == "MAX_LIMIT") { print "MAX_LIMIT = 4.0"; next }
        if (key == "MAX_VELOCITY" || key == "MAX_LINEAR_VELOCITY") { print key " = 20.0"; next }
        if (key == "MAX_ACCELERATION" || key == "MAX_LINEAR_ACCELERATION" || key == "DEFAULT_LINEAR_ACCELERATION") {
            print key " = 200.0"; next
        }
    }
    { print }
' "$sample/lathe.ini" >"$dir/config/lathe.ini"

(
    cd "$dir"
    export RTAPI_UID=65534 RTAPI_FIFO_PATH="$dir/fifo/rtapi_fifo" HOME="$dir/home"
    setsid linuxcnc -r "$dir/config/lathe.ini" </dev/null >"$dir/linuxcnc.log" 2>&1 &
    echo "$! linuxcnc" >"$dir/linuxcnc.pid"
)

# linuxcncrsh listens about 3 s after the start; allow a busy machine much longer.
for waited in $(seq 1 240); do
    if (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; then break; fi
    if ! alive "$(cut -d' ' -f1 "$dir/linuxcnc.pid")"; then
        tail -n 20 "$dir/linuxcnc.log" >&2
        stop "$dir" || true
        fail "LinuxCNC ended during its start (log: $dir/linuxcnc.log)"
    fi
    sleep 0.25
done
if ! (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; then
    tail -n 20 "$dir/linuxcnc.log" >&2
    stop "$dir" || true
    fail "LinuxCNC did not listen on port $port within 60 s (log: $dir/linuxcnc.log)"
fi
# Every component's PID and name, for the stop (some of them leave the linuxcnc script's session).
for name in $components; do
    for pid in $(pgrep -x "$name" || true); do echo "$pid $name"; done
done >"$dir/components.pid"

echo "export TRUETURN_LINUXCNC_URL=linuxcnc://127.0.0.1:$port"
echo "export TRUETURN_LINUXCNC_DIR=$dir"
