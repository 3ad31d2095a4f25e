"""Template statistics and solving checks over a few seeds."""

from __future__ import annotations

from .template_expand import _expand, _rng, expand_template
from .template_model import Template, TemplateCheck, TemplateStats


def template_stats(template: Template, seeds: range | list[int] | tuple[int, ...] = range(8)
                   ) -> TemplateStats:
    """Objects, relations and floor area of a template's expansions over some seeds."""
    from shapely.geometry import Polygon

    n_obj, area, n_rel = [], [], []
    for s in seeds:
        doc, _ = _expand(template.data, template.motifs, _rng(template, s))
        n_obj.append(len(doc["objects"]))
        n_rel.append(len(doc["relations"]))
        area.append(float(Polygon(doc["room"]["footprint"]).area))
    return TemplateStats(template.name, tuple(int(s) for s in seeds), tuple(n_obj), tuple(area),
                         tuple(n_rel))


def check_template(template: Template, seeds: range | list[int] | tuple[int, ...] = range(2),
                   *, library=None) -> TemplateCheck:
    """Expand a template for some seeds and solve each (no settling).

    Parameters
    ----------
    template : Template
    seeds : iterable of int
        Each seed expands the template and seeds the solver.
    library : parse3d.solver.AssetLibrary, optional
        Shared asset library (default: the process-wide pool).

    Returns
    -------
    TemplateCheck
    """
    import time

    from ..solver import solve

    n_obj, n_placed, fails, secs = [], [], [], []
    for s in seeds:
        pag = expand_template(template, s)
        t0 = time.perf_counter()
        scene = solve(pag, seed=int(s), library=library, validate=False)
        secs.append(time.perf_counter() - t0)
        n_obj.append(len(pag.objects))
        n_placed.append(len(scene.placed))
        fails += [(int(s), o.id, o.reason or "") for o in scene.failed]
    return TemplateCheck(template.name, tuple(int(s) for s in seeds), tuple(n_obj),
                         tuple(n_placed), tuple(fails), tuple(secs))
