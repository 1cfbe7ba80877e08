"""These problem files are broken on purpose (tests/test_validate.py proves that `lagrade validate`
says how): the lagrade pytest plugin must not collect them as the repository's own problems."""

collect_ignore_glob = ["problems/*", "reference_solutions/*"]
