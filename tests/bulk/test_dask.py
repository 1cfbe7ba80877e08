"""The Dask path on a LocalCluster: the same grades as the process pool, by construction."""

from __future__ import annotations

import classgen
import pytest
from classcheck import assert_expected, stored
from click.testing import CliRunner

from lagrade.uses.bulk.assignment import load_assignment
from lagrade.uses.bulk.runner import grade_folder
from lagrade.cli.bulk import grade

distributed = pytest.importorskip("distributed", reason="the dask extra is not installed (pip install lagrade[dask])")


def test_dask_local_cluster(tmp_path, sentinel):
    root = tmp_path / "submissions"
    expected = classgen.make_class(root, 12, problems=["12.43", "12.3"], sentinel=sentinel, extras=False)
    hw = tmp_path / "hw.toml"
    hw.write_text(classgen.assignment_toml(["12.43", "12.3"]))
    db = tmp_path / "dask.sqlite"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        res = CliRunner().invoke(grade, [str(root), "--assignment", str(hw), "--db", str(db),
                                         "--scheduler", cluster.scheduler_address, "--no-summary"])
        assert res.exit_code == 0, res.output
        assert "Dask threads" in res.output
        assert_expected(db, expected)
        # a second run on the cluster grades nothing
        with distributed.Client(cluster) as client:
            assert grade_folder(root, load_assignment(hw), db, scheduler=client).todo == 0
            from lagrade.uses.bulk.runner import dask_stop

            client.run(dask_stop)
    # the local pool agrees part by part
    local = tmp_path / "local.sqlite"
    grade_folder(root, load_assignment(hw), local, workers=2)
    (s1, p1), (s2, p2) = stored(db), stored(local)
    assert {k: v["score"] for k, v in s1.items()} == {k: v["score"] for k, v in s2.items()}
    assert {k: {n: x["verdict"] for n, x in v.items()} for k, v in p1.items()} == \
        {k: {n: x["verdict"] for n, x in v.items()} for k, v in p2.items()}
