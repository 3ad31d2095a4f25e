"""Room templates (``pag-template/1``) and motifs (``pag-motif/1``): PAGs drawn from a seed.

A *template* is a room type's recipe: a room whose width, depth and height are sampled, objects
that may repeat (``count``) or be optional (``p``), relations written as in ``pag/1``, and
*motifs* — reusable groups of objects (a desk set-up, a bed with nightstands) kept in
``motifs/<name>.yaml`` and shared by every template. :func:`expand_template` turns a template
and a seed into an ordinary :class:`~parse3d.pag.PAG`; the format is documented in
``docs/templates.md``.

Loading validates in two layers, like :mod:`parse3d.pag.validate`: the JSON Schema shipped
beside this module first, then meaning (unknown motif or parameter, bad ranges, duplicate ids
after expansion, a repeated parent without ``stack``, ...). Finally the template is expanded
with every optional object present and every count at its maximum, and that PAG is checked by
the ``pag/1`` validator against the asset vocabulary, with each problem mapped back to the line
of the template or motif it came from. Every mistake is an :class:`~parse3d.errors.InputError`
whose problems read ``FILE:/json/pointer: message``.

Examples
--------
>>> from parse3d.datagen.templates import list_templates, expand_template
>>> t = list_templates("study")[0]                                    # doctest: +SKIP
>>> pag = expand_template(t, seed=3)                                  # doctest: +SKIP
>>> pag.name                                                          # doctest: +SKIP
'study-reading-02-s3'
"""

from __future__ import annotations

from .template_check import check_template, template_stats
from .template_expand import expand_template
from .template_load import (
    list_templates,
    load_motif,
    load_template,
    motif_library,
    template_problems,
)
from .template_model import (
    MOTIF_FORMAT,
    ROOM_TYPES,
    TEMPLATE_FORMAT,
    Motif,
    Template,
    TemplateCheck,
    TemplateStats,
    motifs_dir,
    templates_dir,
)

__all__ = [
    "ROOM_TYPES",
    "TEMPLATE_FORMAT",
    "MOTIF_FORMAT",
    "Motif",
    "Template",
    "TemplateStats",
    "TemplateCheck",
    "templates_dir",
    "motifs_dir",
    "load_motif",
    "motif_library",
    "load_template",
    "list_templates",
    "expand_template",
    "template_problems",
    "template_stats",
    "check_template",
]
