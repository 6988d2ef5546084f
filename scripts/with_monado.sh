#!/usr/bin/env bash
# Runs a command against Monado (built by scripts/build_monado.sh): the null compositor (no window, no display
# needed by the runtime), the remote driver on a free TCP port of its own (exported as KUMITE_XR_REMOTE_PORT, so
# parallel tests do not collide), a private XDG_CONFIG_HOME, and no real-time priority for Monado's threads when
# run as root (setpriv drops CAP_SYS_NICE). Without DISPLAY the command runs under xvfb-run (kumite renders with
# OpenGL through GLX).
#   scripts/with_monado.sh [--port N] [--monado BUILD_DIR] COMMAND [ARGS...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
port="" monado=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --port) port="$2"; shift 2 ;;
    --monado) monado="$2"; shift 2 ;;
    --) shift; break ;;
    *) break ;;
  esac
done
[[ $# -gt 0 ]] || { echo "usage: scripts/with_monado.sh [--port N] [--monado BUILD_DIR] COMMAND [ARGS...]" >&2; exit 2; }
[[ -n "$monado" ]] || monado="$("$root/scripts/build_monado.sh")"
manifest="$monado/openxr_monado-dev.json"
[[ -f "$manifest" ]] || { echo "with_monado: no runtime manifest $manifest (run scripts/build_monado.sh)" >&2; exit 1; }
if [[ -z "$port" ]]; then
  port="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
fi
config="$(mktemp -d)"
trap 'rm -rf "$config"' EXIT
mkdir -p "$config/monado"
printf '{"active": "remote", "remote": {"version": 0, "port": %d, "view_count": 2}}\n' "$port" >"$config/monado/config_v0.json"
export XR_RUNTIME_JSON="$manifest" XRT_COMPOSITOR_NULL=1 P_OVERRIDE_ACTIVE_CONFIG=remote XDG_CONFIG_HOME="$config" \
       KUMITE_XR_REMOTE_PORT="$port"
prefix=()
[[ $(id -u) -eq 0 ]] && command -v setpriv >/dev/null && prefix=(setpriv --bounding-set -sys_nice)
if [[ -z "${DISPLAY:-}" ]]; then
  prefix=(xvfb-run -a -s "-screen 0 640x480x24" "${prefix[@]}")
fi
status=0
"${prefix[@]}" "$@" || status=$?
exit "$status"
