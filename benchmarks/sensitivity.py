"""What error each accuracy preset catches (lagrade.uses.research.sensitivity): every dynamics part, each
parameter scaled by (1 + eps), graded under fast, default and strict.

    python benchmarks/sensitivity.py                 # every problem (about 2 minutes)
    python benchmarks/sensitivity.py 12.14 12.22     # some
    python benchmarks/sensitivity.py --markdown      # the summary table of docs/numerics.md
"""

from __future__ import annotations

import argparse
import time

from lagrade.problem.library import problem_ids
from lagrade.uses.research.sensitivity import markdown, scan


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ids", nargs="*")
    ap.add_argument("--markdown", action="store_true", help="print the summary table for docs/numerics.md")
    args = ap.parse_args()
    t0 = time.perf_counter()
    rows = scan(args.ids or problem_ids())
    print(f"\n{len(rows)} parts in {time.perf_counter() - t0:.0f} s")
    if args.markdown:
        print(markdown(rows))


if __name__ == "__main__":
    main()
