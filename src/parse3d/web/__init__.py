"""The PAG designer: a local web app over the library (``parse3d serve``).

:func:`create_app` builds the FastAPI application: a JSON API (vocabulary, asset previews,
validation, solving with progress, templates, PAG files in one working folder) and the
browser front end shipped under ``static/``. See ``docs/web.md``.
"""

from .app import MAX_BODY_BYTES, create_app

__all__ = ["create_app", "MAX_BODY_BYTES"]
