"""The server's queue on a Dask cluster (a LocalCluster): bulk grading's Dask task, the same grades."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient
from serverkit import GOLDEN, bearer, expectations, make_config

from lagrade.uses.server.app import create_app

pytestmark = pytest.mark.slow
distributed = pytest.importorskip("distributed", reason="the dask extra is not installed (pip install lagrade[dask])")


def test_graded_on_a_local_cluster(tmp_path):
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        app = create_app(make_config(tmp_path, scheduler=cluster.scheduler_address))
        try:
            with TestClient(app) as client:
                path = GOLDEN / "12.22" / "wrong_sign_of_V.py"
                r = client.post("/api/v1/problems/12.22/check", headers=bearer(app, "alice"),
                                files={"file": ("answer.py", path.read_bytes())})
                assert r.status_code == 200, r.text
                verdicts = {p["part"]: p["verdict"] for p in r.json()["parts"]}
                assert verdicts == {**verdicts, **expectations(path)}
                assert app.state.server.db.counts() == {"graded": 1}
        finally:
            with distributed.Client(cluster) as c:
                from lagrade.uses.bulk.runner import dask_stop

                c.run(dask_stop)
