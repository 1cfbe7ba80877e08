"""What simulating only a scene's declared effects saves, on the grading path: per scene, the median time
of the dynamics part's trajectory check (`compare_runs` as the checker calls it) with the model built
from the declared effects and with the same builder's all-machinery model, on the same path, side by
side in one run (the repeats alternated).

    python benchmarks/effects.py [IDS...]

See lagrade.uses.research.effectsbench. The scenes: chapter problems with different effects, and the dry
friction (stick-slip) test scene, the one that declares switching.
"""

from __future__ import annotations

import sys

from lagrade.uses.research.effectsbench import COULOMB, compare_scene, format_rows

REPEAT = 9
IDS = ("12.43", "12.14", "12.7", "12.16", "12.22", "12.34", "12.35", "12.4", "12.23", "12.49", COULOMB)

if __name__ == "__main__":
    ids = sys.argv[1:] or IDS
    rows = [compare_scene(pid, repeat=REPEAT) for pid in ids]
    print(format_rows(rows))
    total_d = sum(r.ms_declared for r in rows)
    total_a = sum(r.ms_all for r in rows)
    print(f"\ntotal ms: declared {total_d:.2f}, all machinery {total_a:.2f} ({total_a / total_d:.2f}x)")
