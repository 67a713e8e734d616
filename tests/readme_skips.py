#!/usr/bin/env python3
"""readme_skips.py - the reason of every test ctest skipped, after the run:
what the README promises ("each prints its reason").  CTest 3.25's summary
says only "(Skipped)", so `make test` runs ctest with --output-junit and
this reads that file: for each skipped test, its name and its reason, the
first output line that says one (SKIP:, KIT-SKIP:, skipped:, or a line of
the Check suites' "skipped"), else its last output line.

Usage: readme_skips.py JUNIT.xml   (exit 0 always: a report, not a check)
"""

import re
import sys
import xml.etree.ElementTree as ET

REASON = re.compile(r"(SKIP|skip)", re.IGNORECASE)


def main():
    try:
        root = ET.parse(sys.argv[1]).getroot()
    except (OSError, ET.ParseError, IndexError) as e:
        print("readme_skips: cannot read the JUnit file: %s" % e)
        return 0
    skipped = []
    for case in root.iter("testcase"):
        if case.find("skipped") is None:
            continue
        out = case.findtext("system-out") or ""
        lines = [l.strip() for l in out.splitlines() if l.strip()]
        reason = next((l for l in lines if REASON.search(l)),
                      lines[-1] if lines else "(no reason printed)")
        skipped.append((case.get("name"), reason))
    if skipped:
        print("Skipped, and why:")
        for name, reason in skipped:
            print("  %s: %s" % (name, reason))
    return 0


if __name__ == "__main__":
    sys.exit(main())
