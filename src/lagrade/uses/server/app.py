"""The FastAPI application: ``create_app(ServerConfig)``; uvicorn serves it (``lagrade serve``).

Everything the routes share lives in one :class:`lagrade.uses.server.state.Server` on ``app.state``.
"""

from __future__ import annotations

from contextlib import asynccontextmanager

from fastapi import FastAPI, Request
from fastapi.exception_handlers import http_exception_handler, request_validation_exception_handler
from fastapi.exceptions import RequestValidationError
from starlette.exceptions import HTTPException as StarletteHTTPException

from lagrade.uses.server import api, web
from lagrade.uses.server.config import ServerConfig
from lagrade.uses.server.limits import BodyLimit
from lagrade.uses.server.state import Server


def create_app(config: ServerConfig, *, grade: bool = True) -> FastAPI:
    """The ASGI app. ``grade=False`` starts no graders (tests of what needs none)."""
    server = Server(config)
    server.grades = grade
    lti_ = _lti(config, server)

    @asynccontextmanager
    async def lifespan(app: FastAPI):
        if grade:
            server.start()
        if lti_ is not None:  # grades go back to the LMS as they are written
            if server.queue is not None:
                server.queue.on_graded = lti_.wake
            lti_.start()
        try:
            yield
        finally:
            if lti_ is not None:
                lti_.stop()
            server.stop()

    # the OpenAPI document is served (/openapi.json); the Swagger and ReDoc pages are not: they load
    # their scripts from a CDN, and nothing here fetches anything from outside
    app = FastAPI(title="lagrade", version="1", lifespan=lifespan, docs_url=None, redoc_url=None,
                  description="Check answers to the problems of an assignment; the references stay on the server.")
    app.state.server = server
    app.state.lti = lti_
    app.include_router(api.router)
    if lti_ is not None:
        from lagrade.uses.server.lti import router as lti_router

        app.include_router(lti_router)
    app.include_router(web.router)
    app.add_middleware(BodyLimit, max_bytes=config.max_body)

    # the API answers errors as JSON (one line in `detail`); a browser's pages as a page of the site
    @app.exception_handler(StarletteHTTPException)
    async def http_error(request: Request, exc: StarletteHTTPException):
        if _api(request):
            return await http_exception_handler(request, exc)
        return web.error_page(request, exc.status_code, str(exc.detail), getattr(exc, "headers", None))

    @app.exception_handler(RequestValidationError)
    async def invalid_request(request: Request, exc: RequestValidationError):
        if _api(request):
            return await request_validation_exception_handler(request, exc)
        return web.error_page(request, 422, web.one_line_invalid(exc))

    return app


def _lti(config: ServerConfig, server: Server):
    """The LTI 1.3 side (lti.py), when ``config.lti`` names the platforms; None otherwise."""
    if config.lti is None:
        return None
    try:
        from lagrade.uses.server.lti import Lti, load_config

        return Lti(load_config(config.lti), server)
    except ImportError as exc:
        server.stop()
        raise ValueError(f"--lti needs pylti1p3 ({exc.name} is missing): pip install 'lagrade[server]'") from None
    except Exception:
        server.stop()
        raise


def _api(request: Request) -> bool:
    path = request.url.path
    return path.startswith("/api/") or path in ("/openapi.json", "/healthz")

