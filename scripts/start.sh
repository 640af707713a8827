#!/usr/bin/env bash
# npm start: set up what is missing, build native + wasm, serve the page on http://localhost:5173.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh all
exec npm run dev
