"""Physics: settling scenes in SAPIEN 3 and extracting part-level contact graphs.

- :func:`settle` — simulate a solved scene under gravity (paper: 1000 steps of 0.01 s,
  damping 0.05 / 0.5) and write the settled poses and flags into it;
- :func:`extract_contacts` — the part-level contact graph (pairs of parts within 1 mm);
- :func:`contacts_to_json`, :func:`contact_graph` — ``contacts.json`` rows and a networkx graph;
- :mod:`parse3d.physics.collision` — engine-neutral convex collision data, cached per asset;
- :mod:`parse3d.physics.mujoco` — the same scene in MuJoCo, as an independent check.
"""

from .collision import asset_collision, scene_bodies, shell_collision
from .contacts import contact_graph, contacts_from_json, contacts_to_json, extract_contacts
from .settle import ObjectMotion, SettleConfig, SettleReport, settle

__all__ = [
    "settle",
    "SettleConfig",
    "SettleReport",
    "ObjectMotion",
    "extract_contacts",
    "contacts_to_json",
    "contacts_from_json",
    "contact_graph",
    "asset_collision",
    "scene_bodies",
    "shell_collision",
]
