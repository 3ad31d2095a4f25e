"""Dataset generation: room templates and motifs that expand into PAGs (``templates``).

See ``docs/templates.md`` for the ``pag-template/1`` and ``pag-motif/1`` formats.
"""

from .templates import (
    ROOM_TYPES,
    Motif,
    Template,
    check_template,
    expand_template,
    list_templates,
    load_motif,
    load_template,
    motif_library,
    template_stats,
)

__all__ = [
    "ROOM_TYPES",
    "Motif",
    "Template",
    "check_template",
    "expand_template",
    "list_templates",
    "load_motif",
    "load_template",
    "motif_library",
    "template_stats",
]
