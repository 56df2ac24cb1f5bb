#!/bin/sh
# style_tests.sh - every doc/styles page names its tests (a closing line
# written by tools/style_tests.py) and every test path a page names exists.
cd "$(dirname "$0")/../.." || exit 1
exec /usr/bin/python3 tools/style_tests.py --check
