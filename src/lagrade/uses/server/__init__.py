"""``lagrade serve``: a course server that grades, so that students hold nothing but their answers.

Layers: the server sits on top of bulk grading (its warm grader processes, its gradebook schema)
and imports from it; nothing below imports from here. Modules: ``config`` (settings), ``db``
(SQLAlchemy tables: the gradebook's and the server's own), ``tokens`` (signed student tokens),
``answers`` (a JSON answer as ``answer.toml`` text, the "read as" preview), ``grading`` (the queue
in front of the warm graders), ``limits`` (request size, rate limits), ``app`` (the FastAPI
factory), ``api`` and ``web`` (routes), ``client`` (``lagrade check --server``).
"""
