"""The Part-Aware Spatial Configuration Solver (Algorithm 1 of the paper) and its search.

Modules follow the algorithm's stages: ``support`` (stage 2), ``rotation`` (3), ``regions``
(4-5), ``placement`` (1 and 6 for one object: instance choice in ``choice``, positions in
``sampling``, piles in ``stacking``, pose checks in ``validation``), ``search`` (the loop over
objects, failure propagation, backjumping, re-placement for repair). What a relation means to
the solver is one rule per relation family in ``rules`` (``support``, ``contact``,
``alignment``, ``layout``), registered by name in ``rules.RULES``.

>>> import parse3d
>>> scene = parse3d.solve(parse3d.load_pag("examples/study.json"), seed=0)  # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Callable

from ..errors import InfeasibleError
from ..measure.checks import check_relations
from ..pag.canonical import canonical_document
from ..pag.model import PAG
from ..scene.model import Scene
from ..words import Resolver
from .config import SEARCHES, STRATEGIES, SolverConfig
from .library import AssetLibrary
from .search import SolveProgress, solve_scene

__all__ = ["solve", "SolverConfig", "SolveProgress", "AssetLibrary", "check_relations",
           "STRATEGIES", "SEARCHES"]


def canonical_pag(pag: PAG, vocabulary) -> PAG:
    """``pag`` with its words resolved (:func:`parse3d.pag.canonical.canonical_document`): a
    hypernym becomes the list of its members the solver draws among, a synonym its category,
    a part word its label. The same object when every word already is one.

    ``vocabulary`` is the category vocabulary or a function giving it, called only when some
    word is not plainly a category name or a label (bundled templates never need it)."""
    if _plain_words(pag):
        return pag
    if callable(vocabulary):
        vocabulary = vocabulary()
    data = pag.to_dict()
    out = canonical_document(data, Resolver(vocabulary))
    return pag if out is data else PAG.from_dict(out)


def _plain_words(pag: PAG) -> bool:
    """Every category word is written as a category is named and is no hypernym or synonym,
    and no part word is one the vocabulary file lists (what a validated PAG then means). A
    word that may be a plural (``couches``, ``legs``) is plain only when it is itself a
    category or a label of its object's categories (``hanging_clothes``): only the library's
    vocabulary tells them apart, so it is read for such words alone."""
    from functools import cache

    from ..words import lexicon, normalize, singulars

    @cache
    def vocab():
        from ..assets.registry import vocabulary

        return vocabulary()

    lex = lexicon()
    for node in pag.objects.values():
        for c in node.candidates:
            if c != normalize(c) or c in lex.hypernyms or c in lex.synonyms:
                return False
            if singulars(c) and not vocab().has_category(c):
                return False
    for e in pag.relations:
        for ref in (e.child, e.parent):
            if ref.part is None or ref.object not in pag.objects:
                continue
            if ref.part != normalize(ref.part):
                return False
            cands = pag.objects[ref.object].candidates
            if singulars(ref.part) and not all(
                    vocab().has_category(c) and ref.part in vocab().parts(c) for c in cands):
                return False
            for c in cands:
                if ref.part in lex.parts.get(c, ()) or any(
                        ref.part in lex.parts.get(h, ()) for h, ms in lex.hypernyms.items() if c in ms):
                    return False
    return True


def solve(pag: PAG, seed: int = 0, *, library: AssetLibrary | None = None,
          config: SolverConfig | None = None, validate: bool = True,
          progress: Callable[[SolveProgress], None] | None = None,
          deadline: float | None = None, proposals: dict | None = None,
          strict: bool = False) -> Scene:
    """Turn a PAG into a Scene.

    Parameters
    ----------
    pag : PAG
        The graph (validated first, against the asset registry's vocabulary, unless
        ``validate=False``). Its words are resolved first (:func:`canonical_pag`): the scene
        holds the resolved graph, and each object's category is the one drawn.
    seed : int
        Scene seed; the same PAG, seed and library give the same scene.
    library : AssetLibrary, optional
        Where assets come from (default: the on-disk pool).
    config : SolverConfig, optional
    progress : callable, optional
        Called with a :class:`SolveProgress` each time an object is placed or fails.
    deadline : float, optional
        Seconds; objects not placed by then fail with ``time limit``.
    proposals : dict of str to (R (3, 3), t (3,)) or (R, t, asset, scale), optional
        World poses (rotation, asset-origin position in metres) tried first per object id;
        with an :class:`~parse3d.assets.Asset` and its uniform scale, the first attempt places
        that asset at that scale (a generated layout's own assets).
    strict : bool
        Raise :class:`InfeasibleError` (carrying the scene as its report) when an object fails.

    Returns
    -------
    Scene
        Failed objects are marked ``failed`` with the constraint that could not be met; check
        ``scene.ok``. (The CLI turns failures into exit code 3.)

    Raises
    ------
    InputError
        The PAG is invalid.
    InfeasibleError
        With ``strict=True``, when some object could not be placed.
    """
    from ..assets.registry import vocabulary

    if validate:
        vocab = vocabulary()
        pag.validate(vocabulary=vocab)
        pag = canonical_pag(pag, vocab)
    else:
        pag = canonical_pag(pag, vocabulary)
    scene = solve_scene(pag, seed=seed, library=library, config=config, progress=progress,
                        deadline=deadline, proposals=proposals)
    if strict and not scene.ok:
        first = scene.failed[0]
        raise InfeasibleError(f"{len(scene.failed)} of {len(scene.objects)} objects could not be "
                              f"placed; {first.id}: {first.reason}", report=scene)
    return scene
