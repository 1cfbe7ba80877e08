"""What lagrade is used for: a class (``bulk``), the course server (``server``), the deployments
(``deploy``), the pytest plugin, and the research code that ``lagrade bench`` runs (never imported
by grading).
"""
