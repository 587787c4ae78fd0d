#!/usr/bin/env bash
# Runs a command with RADIOSITY_DEVICE set, or skips (exit 77) when no such device exists here.
# Usage: on_device.sh RADIOSITY DEVICE COMMAND...
set -uo pipefail
radiosity=$1 device=$2
shift 2
if ! "$radiosity" devices 2>/dev/null | grep -qi -- "$device"; then
  echo "no '$device' OpenCL device here: skipped"
  exit 77
fi
RADIOSITY_DEVICE=$device exec "$@"
