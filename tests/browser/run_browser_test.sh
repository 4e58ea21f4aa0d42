#!/usr/bin/env bash
# The review page in headless Chromium (review_browser_test.mjs), as a ctest:
#   run_browser_test.sh FLUENCE REVIEW_REFERENCE WORK_DIR
# Installs puppeteer-core from package-lock.json into WORK_DIR (npm ci, once). Exits 77 (ctest
# SKIP_RETURN_CODE, reported as skipped with the reason) only when Chromium, Node.js or npm is not
# installed or puppeteer-core cannot be installed; every other failure fails the test.
set -euo pipefail
fluence=$1 reference=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
chromium=$(command -v chromium || command -v chromium-browser || true)
if [[ -z "$chromium" ]]; then
  echo "SKIPPED: no chromium in PATH (apt-get install chromium; scripts/install_dependencies.sh installs it)"
  exit 77
fi
for tool in node npm; do
  if ! command -v $tool >/dev/null; then
    echo "SKIPPED: no $tool in PATH (apt-get install nodejs npm)"
    exit 77
  fi
done
mkdir -p "$work"
if ! cmp -s "$here/package-lock.json" "$work/package-lock.json" || [[ ! -d "$work/node_modules/puppeteer-core" ]]; then
  cp "$here/package.json" "$here/package-lock.json" "$work/"
  if ! (cd "$work" && npm ci --no-audit --no-fund --silent); then
    echo "SKIPPED: npm ci could not install puppeteer-core into $work (no network?)"
    exit 77
  fi
fi
exec node "$here/review_browser_test.mjs" "$fluence" "$reference" "$chromium" "$work"
