#!/usr/bin/env bash
# The main job of `make demo`.
set -euo pipefail
build=${1:-build}
echo "vroc: demo not yet available"
