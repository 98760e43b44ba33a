#!/usr/bin/env bash
# Starts a throw-away PostgreSQL server for the storage tests and prints the address to export:
#   eval "$(scripts/start-test-postgres.sh DIR [FIRST_PORT])"   ->   TRUETURN_PG_URL=postgresql://...
# Stop it with: scripts/start-test-postgres.sh --stop DIR
# The cluster lives in DIR (recreated each time; the postgres user must be able to reach it, so
# use a folder under /tmp), listens on 127.0.0.1 only on the first free port from FIRST_PORT
# (default 55432), trust authentication.
set -euo pipefail

pg_bin=$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -n 1)
[[ -x "$pg_bin/initdb" ]] || { echo "start-test-postgres: PostgreSQL server binaries not found" >&2; exit 1; }

as_postgres() {
    if [[ $(id -u) -eq 0 ]]; then runuser -u postgres -- "$@"; else "$@"; fi
}

if [[ "${1:-}" == "--stop" ]]; then
    dir=$(realpath "$2")
    [[ -d "$dir/data" ]] && as_postgres "$pg_bin/pg_ctl" -D "$dir/data" -m fast stop >/dev/null 2>&1 || true
    exit 0
fi

dir=$(realpath -m "${1:?usage: start-test-postgres.sh DIR [FIRST_PORT]}")
first_port="${2:-55432}"
if [[ -d "$dir/data" ]]; then as_postgres "$pg_bin/pg_ctl" -D "$dir/data" -m fast stop >/dev/null 2>&1 || true; fi
rm -rf "$dir"
mkdir -p "$dir"
if [[ $(id -u) -eq 0 ]]; then
    chown postgres:postgres "$dir"
fi
as_postgres "$pg_bin/initdb" -D "$dir/data" -U trueturn --auth=trust -E UTF8 --no-locale >"$dir/initdb.log" 2>&1 \
    || { cat "$dir/initdb.log" >&2; exit 1; }
for port in $(seq "$first_port" $((first_port + 40))); do
    if as_postgres "$pg_bin/pg_ctl" -D "$dir/data" -l "$dir/server.log" -w -t 30 \
        -o "-p $port -c listen_addresses=127.0.0.1 -k $dir -c fsync=off -c full_page_writes=off" start >/dev/null; then
        break
    fi
    grep -q "could not bind\|already in use" "$dir/server.log" || { cat "$dir/server.log" >&2; exit 1; }
    port=""
done
[[ -n "$port" ]] || { echo "start-test-postgres: no free port from $first_port" >&2; exit 1; }
echo "export TRUETURN_PG_URL=postgresql://trueturn@127.0.0.1:$port/postgres"
