#!/bin/sh
# Check the HTML report in a real headless browser (Debian's chromium), then keep a screenshot.
#
#   scripts/check_report_in_browser.sh            # installs chromium if missing (needs root), runs the test
#   SCREENSHOT_DIR=/tmp/shots scripts/check_report_in_browser.sh
#
# The pytest test tests/bulk/test_exports_report.py::test_report_in_headless_chromium grades a small
# class, writes the report, loads every page in chromium and checks that it loads, that no script or
# resource failed (the page counts errors into <body data-errors>) and that the numbers shown are the
# ones in the database. Without chromium that test is skipped with the reason; this script makes it run.
set -eu
cd "$(dirname "$0")/.."
if ! command -v chromium >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ]; then
        apt-get update && apt-get install -y chromium
    else
        echo "chromium is missing: sudo apt-get install -y chromium" >&2
        exit 2
    fi
fi
python -m pytest -q -p no:cacheprovider "tests/bulk/test_exports_report.py::test_report_in_headless_chromium" -rs

# A screenshot of a generated report, to look at.
out="${SCREENSHOT_DIR:-$(mktemp -d)}"
mkdir -p "$out"
work="$(mktemp -d)"
mkdir -p "$work/submissions/ada" "$work/submissions/bob"
cp reference_solutions/12.43/answer.py "$work/submissions/ada/12.43.py"
cp tests/answers/12.43/wrong_sign_of_V.py "$work/submissions/bob/12.43.py"
printf 'name = "demo"\n[[problems]]\nid = "12.43"\n' > "$work/hw.toml"
python -c "import sys; from lagrade.cli.bulk import grade; grade(sys.argv[1:])" \
    "$work/submissions" -a "$work/hw.toml" --db "$work/hw.sqlite" --no-summary --no-progress >/dev/null
python -c "import sys; from lagrade.cli.bulk import report; report(sys.argv[1:])" \
    "$work/hw.sqlite" --html "$work/report" >/dev/null
for page in index students/bob; do
    chromium --headless --no-sandbox --disable-gpu --window-size=1200,1400 \
        --screenshot="$out/$(basename $page).png" "file://$work/report/$page.html" 2>/dev/null
done
echo "screenshots: $out/index.png $out/bob.png"
rm -rf "$work"
