#!/usr/bin/env bash
# Starts a throw-away PostgreSQL server for the storage tests and prints the address to export:
#   eval "$(scripts/start-test-postgres.sh DIR [FIRST_PORT])"   ->   TRUETURN_PG_URL=postgresql://...
# Stop it with: scripts/start-test-postgres.sh --stop DIR
# The cluster lives in DIR (recreated each time; the postgres user must be able to reach it, so
# use a folder under /tmp), listens on 127.0.0.1 only on the first free port from FIRST_PORT
# (default 55432), trust authentication.
#
# The plant database's roles (docs/DECISIONS.md, "The plant-wide history"): the group roles trueturn_terminal and
# trueturn_quality (the history migration creates them too, when missing) and the logins the tests use:
# terminal_m1 .. terminal_m20 (members of trueturn_terminal; which machine each may write is a row of the
# database's plant_terminals table, which the test inserts) and quality (member of trueturn_quality).
#
# More for the tests of the plant-wide history:
#   scripts/start-test-postgres.sh --crash DIR           stops the server at once (pg_ctl stop -m immediate)
#   scripts/start-test-postgres.sh --restart DIR         starts it again on the same port
#   eval "$(scripts/start-test-postgres.sh --standby DIR PRIMARY_DIR [FIRST_PORT])"
#                                                         a streaming hot standby of the server in PRIMARY_DIR
#                                                         -> TRUETURN_PG_STANDBY_URL=postgresql://...
set -euo pipefail

pg_bin=$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -n 1)
[[ -x "$pg_bin/initdb" ]] || { echo "start-test-postgres: PostgreSQL server binaries not found" >&2; exit 1; }

as_postgres() {
    if [[ $(id -u) -eq 0 ]]; then runuser -u postgres -- "$@"; else "$@"; fi
}

# start_on_free_port DIR FIRST_PORT: starts the cluster in DIR/data on the first free port, writes it to DIR/port.
start_on_free_port() {
    local dir="$1" first="$2" port
    for port in $(seq "$first" $((first + 40))); do
        if as_postgres "$pg_bin/pg_ctl" -D "$dir/data" -l "$dir/server.log" -w -t 60 \
            -o "-p $port -c listen_addresses=127.0.0.1 -k $dir -c fsync=off -c full_page_writes=off" start >/dev/null; then
            echo "$port" >"$dir/port"
            return 0
        fi
        grep -q "could not bind\|already in use" "$dir/server.log" || { cat "$dir/server.log" >&2; exit 1; }
    done
    echo "start-test-postgres: no free port from $first" >&2
    exit 1
}

fresh_dir() {
    local dir="$1"
    if [[ -d "$dir/data" ]]; then as_postgres "$pg_bin/pg_ctl" -D "$dir/data" -m fast stop >/dev/null 2>&1 || true; fi
    rm -rf "$dir"
    mkdir -p "$dir"
    if [[ $(id -u) -eq 0 ]]; then chown postgres:postgres "$dir"; fi
}

case "${1:-}" in
    --stop)
        dir=$(realpath "$2")
        [[ -d "$dir/data" ]] && as_postgres "$pg_bin/pg_ctl" -D "$dir/data" -m fast stop >/dev/null 2>&1 || true
        exit 0 ;;
    --crash)
        dir=$(realpath "$2")
        as_postgres "$pg_bin/pg_ctl" -D "$dir/data" -m immediate stop >/dev/null
        exit 0 ;;
    --restart)
        dir=$(realpath "$2")
        port=$(cat "$dir/port")
        as_postgres "$pg_bin/pg_ctl" -D "$dir/data" -l "$dir/server.log" -w -t 60 \
            -o "-p $port -c listen_addresses=127.0.0.1 -k $dir -c fsync=off -c full_page_writes=off" start >/dev/null
        exit 0 ;;
    --standby)
        dir=$(realpath -m "${2:?usage: start-test-postgres.sh --standby DIR PRIMARY_DIR [FIRST_PORT]}")
        primary=$(realpath "${3:?usage: start-test-postgres.sh --standby DIR PRIMARY_DIR [FIRST_PORT]}")
        fresh_dir "$dir"
        as_postgres "$pg_bin/pg_basebackup" -h 127.0.0.1 -p "$(cat "$primary/port")" -U trueturn -D "$dir/data" \
            -R -X stream >"$dir/basebackup.log" 2>&1 || { cat "$dir/basebackup.log" >&2; exit 1; }
        start_on_free_port "$dir" "${4:-56432}"
        echo "export TRUETURN_PG_STANDBY_URL=postgresql://trueturn@127.0.0.1:$(cat "$dir/port")/postgres"
        exit 0 ;;
esac

dir=$(realpath -m "${1:?usage: start-test-postgres.sh DIR [FIRST_PORT]}")
first_port="${2:-55432}"
fresh_dir "$dir"
as_postgres "$pg_bin/initdb" -D "$dir/data" -U trueturn --auth=trust -E UTF8 --no-locale >"$dir/initdb.log" 2>&1 \
    || { cat "$dir/initdb.log" >&2; exit 1; }
start_on_free_port "$dir" "$first_port"
port=$(cat "$dir/port")

roles="DO \$\$ BEGIN
  IF NOT EXISTS (SELECT FROM pg_roles WHERE rolname = 'trueturn_terminal') THEN CREATE ROLE trueturn_terminal NOLOGIN; END IF;
  IF NOT EXISTS (SELECT FROM pg_roles WHERE rolname = 'trueturn_quality') THEN CREATE ROLE trueturn_quality NOLOGIN; END IF;
  FOR i IN 1..20 LOOP EXECUTE format('CREATE ROLE terminal_m%s LOGIN IN ROLE trueturn_terminal', i); END LOOP;
  CREATE ROLE quality LOGIN IN ROLE trueturn_quality;
END \$\$;"
as_postgres "$pg_bin/psql" -q -h "$dir" -p "$port" -U trueturn -d postgres -v ON_ERROR_STOP=1 -c "$roles" >/dev/null
echo "export TRUETURN_PG_URL=postgresql://trueturn@127.0.0.1:$port/postgres"
