#!/usr/bin/env bash
# Regenerates the pictures in docs/ with the inspector's headless mode (no display needed).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/app/lloydscope
$bin inspect assets/bumpy_disk.off --no-timings --iteration 0 --screenshot docs/inspector_iteration0.png
$bin inspect assets/bumpy_disk.off --no-timings --iteration 10 --screenshot docs/inspector_iteration10.png
$bin inspect assets/bumpy_disk.off --no-timings --screenshot docs/inspector_converged.png
