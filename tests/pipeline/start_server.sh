# Sourced by the pipeline example runners: starts getme-server ($1) on a free loopback port in the
# current directory (log: server.log), sets server_address, and stops it (SIGTERM) on exit.
start_getme_server() {
  # The background job opens server.log only once it has forked; create it first so that the
  # first read below cannot race the redirection (it did, once, under ASan's slower start).
  : > server.log
  "$1" --listen 127.0.0.1:0 > server.log 2>&1 &
  server_pid=$!
  trap 'kill -TERM "$server_pid" 2> /dev/null || true; wait "$server_pid" 2> /dev/null || true' EXIT
  local port=""
  for _ in $(seq 100); do
    port="$(sed -n 's/.*getme-server listening on port \([0-9]*\).*/\1/p' server.log | head -n 1)"
    [ -n "$port" ] && break
    sleep 0.1
  done
  [ -n "$port" ] || { echo "getme-server did not start: $(cat server.log)"; exit 1; }
  server_address="127.0.0.1:$port"
}
