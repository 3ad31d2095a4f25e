"""The snapshot of validated templates: used while current, ignored once a file changes."""

from __future__ import annotations

import shutil

import pytest

from parse3d.datagen import template_load
from parse3d.datagen.template_model import motifs_dir, templates_dir
from parse3d.datagen.template_snapshot import SNAPSHOT_NAME
from parse3d.errors import InputError


@pytest.fixture()
def folders(tmp_path, monkeypatch):
    """Two bundled study templates and the bundled motifs, copied; a cache of our own."""
    root = tmp_path / "templates"
    (root / "study").mkdir(parents=True)
    for p in sorted((templates_dir() / "study").glob("*.yaml"))[:2]:
        shutil.copy(p, root / "study" / p.name)
    shutil.copytree(motifs_dir(), tmp_path / "motifs")
    cache = tmp_path / "cache"
    cache.mkdir()
    monkeypatch.setenv("PARSE3D_CACHE", str(cache))
    return root, tmp_path / "motifs", cache


def _no_loading(*args, **kwargs):
    raise AssertionError("a template was loaded although the snapshot is current")


def test_snapshot_is_used_then_invalidated_by_an_edit(folders, monkeypatch):
    root, motifs, cache = folders
    first = template_load._load_templates(root, motifs, None)
    assert len(first) == 2 and (cache / SNAPSHOT_NAME).is_file()

    with monkeypatch.context() as m:  # current: nothing is loaded or validated again
        m.setattr(template_load, "load_template", _no_loading)
        again = template_load._load_templates(root, motifs, None)
        assert [t.data for t in again] == [t.data for t in first]
        assert [list(t.motifs) for t in again] == [list(t.motifs) for t in first]
        assert [t.name for t in template_load._load_templates(root, motifs, "study")] == \
            [t.name for t in first]

    # a changed template is read and validated again: the new text, or its error
    path = root / "study" / f"{first[0].name}.yaml"
    text = path.read_text(encoding="utf-8")
    path.write_text(text.replace("description: ", "description: Edited. ", 1), encoding="utf-8")
    edited = template_load._load_templates(root, motifs, None)
    assert edited[0].description.startswith("Edited. ")
    path.write_text(text.replace("room_type: study", "room_type: studdy", 1), encoding="utf-8")
    with pytest.raises(InputError):
        template_load._load_templates(root, motifs, None)

    # so is a changed motif
    path.write_text(text, encoding="utf-8")
    used = sorted(first[0].motifs)[0]
    mpath = motifs / f"{used}.yaml"
    mpath.write_text(mpath.read_text(encoding="utf-8").replace("name: ", "name: x", 1),
                     encoding="utf-8")
    with pytest.raises(InputError):
        template_load._load_templates(root, motifs, None)


def test_damaged_snapshot_is_ignored(folders):
    root, motifs, cache = folders
    first = template_load._load_templates(root, motifs, None)
    (cache / SNAPSHOT_NAME).write_text('{"format": "parse3d-templates/1", "key": ', "utf-8")
    assert [t.data for t in template_load._load_templates(root, motifs, None)] == \
        [t.data for t in first]
