"""What simulating only a scene's declared effects saves: ms per trajectory, side by side in one run.

    python benchmarks/effects.py [IDS...]

For each scene the same sampled trajectories are integrated (DOP853, default tolerances) with the model
assembled from the declared effects, with all machinery compiled (explicit t, velocity-force term,
multipliers and contact events on every constraint, switching events), and with the grader's generic
reference right-hand side. See lagrade.research.effectsbench.
"""

from __future__ import annotations

import sys

from lagrade.research.effectsbench import compare_scene, format_rows

IDS = ("12.43", "12.14", "12.7", "12.16", "12.22", "12.34", "12.35", "12.4", "12.23", "12.49")

if __name__ == "__main__":
    ids = sys.argv[1:] or IDS
    rows = [compare_scene(pid, repeat=5) for pid in ids]
    print(format_rows(rows))
    total_d = sum(r.ms_declared for r in rows)
    total_a = sum(r.ms_all for r in rows)
    total_e = sum(r.ms_engine for r in rows)
    print(f"\ntotal ms/trajectory: declared {total_d:.2f}, all machinery {total_a:.2f} "
          f"({total_a / total_d:.2f}x), generic engine {total_e:.2f} ({total_e / total_d:.2f}x)")
