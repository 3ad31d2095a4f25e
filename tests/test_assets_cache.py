"""The on-disk asset format: exact round trip, fast load, clear errors."""

from __future__ import annotations

import json
import zipfile

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.assets.cache import FORMAT, asset_digest, load_asset, save_asset
from parse3d.errors import AssetError


@pytest.mark.parametrize(("category", "seed"), [("mug", 0), ("dining_table", 1)])
def test_round_trip_is_exact(tmp_path, category, seed):
    a = registry.generate(category, seed)
    path = save_asset(a, tmp_path / "a.npz")
    b = load_asset(path)
    assert asset_digest(b) == asset_digest(a)
    assert (b.category, b.asset_id, b.meta, b.density) == (a.category, a.asset_id, a.meta, a.density)
    assert tuple(b.size_range) == tuple(a.size_range)
    assert [(p.name, p.label, p.watertight, len(p.pieces)) for p in b.parts] == \
        [(p.name, p.label, p.watertight, len(p.pieces)) for p in a.parts]
    for pa, pb in zip(a.parts, b.parts, strict=True):
        np.testing.assert_allclose(pb.mesh.vertices, pa.mesh.vertices, atol=1e-6)
        np.testing.assert_array_equal(pb.mesh.faces, pa.mesh.faces)
        assert pb.material.name == pa.material.name
        assert set(pb.surfaces) == set(pa.surfaces)
        for k, sa in pa.surfaces.items():
            sb = pb.surfaces[k]
            for attr in ("origin", "normal", "u", "v"):
                np.testing.assert_allclose(getattr(sb, attr), getattr(sa, attr), atol=1e-6)
            assert sb.polygon.equals_exact(sa.polygon, 1e-6)
            assert sb.source == sa.source
        for qa, qb in zip(pa.pieces, pb.pieces, strict=True):
            assert qb.is_convex
            # vertices are kept to 1 um: a piece's volume to its area times that (a screw of a
            # few cubic millimetres moves by more than a millionth of itself)
            assert abs(qb.volume - qa.volume) <= 1e-6 * max(qa.volume, 1e-9) + 2e-6 * qa.area
    assert len(b.internal) == len(a.internal)
    for ia, ib in zip(a.internal, b.internal, strict=True):
        assert (ib.part, ib.clearance, ib.depth) == (ia.part, ia.clearance, ia.depth)
        assert ib.surface.polygon.equals_exact(ia.surface.polygon, 1e-6)


def test_internal_surfaces_survive(tmp_path):
    a = registry.generate("mug", 0)
    assert a.internal, "a mug has an inside bottom"
    b = load_asset(save_asset(a, tmp_path / "m.npz"))
    assert np.isinf(b.internal[0].clearance) == np.isinf(a.internal[0].clearance)


def _rewrite_header(path, **changes):
    with np.load(path, allow_pickle=False) as z:
        arrays = {k: z[k] for k in z.files}
    h = json.loads(arrays["header"].tobytes())
    h.update(changes)
    arrays["header"] = np.frombuffer(json.dumps(h).encode(), np.uint8)
    np.savez(path, **arrays)


def test_wrong_format_names_the_file(tmp_path):
    path = save_asset(registry.generate("cup", 0), tmp_path / "old.npz")
    _rewrite_header(path, format="parse3d-asset/0")
    with pytest.raises(AssetError, match=r"old\.npz.*parse3d-asset/0.*" + FORMAT):
        load_asset(path)


def test_not_an_asset_file(tmp_path):
    junk = tmp_path / "junk.npz"
    junk.write_bytes(b"not a zip")
    with pytest.raises(AssetError, match="junk.npz"):
        load_asset(junk)
    other = tmp_path / "other.npz"
    np.savez(other, x=np.zeros(3))
    with pytest.raises(AssetError, match="other.npz.*no header"):
        load_asset(other)
    with pytest.raises(AssetError, match="missing.npz.*not found"):
        load_asset(tmp_path / "missing.npz")


def test_file_is_a_plain_npz_without_pickles(tmp_path):
    path = save_asset(registry.generate("mug", 2), tmp_path / "m.npz")
    with zipfile.ZipFile(path) as z:
        assert "header.npy" in z.namelist()
    with np.load(path, allow_pickle=False) as z:
        assert json.loads(z["header"].tobytes())["format"] == FORMAT
        assert z["p0_v"].dtype == np.float32 and z["p0_f"].dtype == np.int32


def test_fast_npz_reader_matches_numpy(tmp_path):
    """The asset reader's own ``.npy`` header parsing gives numpy's arrays exactly, and hands
    headers it does not know (strings, Fortran order, 0-d) to numpy."""
    from parse3d.assets.cache import _read_npz

    path = save_asset(registry.generate("dresser", 0), tmp_path / "a.npz")
    with np.load(path, allow_pickle=False) as z:
        want = {k: z[k] for k in z.files}
    got = _read_npz(path)
    assert got.keys() == want.keys()
    for k, v in want.items():
        assert got[k].dtype == v.dtype and got[k].shape == v.shape, k
        np.testing.assert_array_equal(got[k], v)
        assert got[k].flags.writeable
    odd = {"s": np.array(["ab", "c"]), "f": np.asfortranarray(np.arange(6.0).reshape(2, 3)),
           "z": np.float32(2.5), "e": np.zeros((0, 3), ">i4"), "b": np.array([True, False])}
    np.savez_compressed(tmp_path / "odd.npz", **odd)
    got = _read_npz(tmp_path / "odd.npz")
    for k, v in odd.items():
        assert got[k].dtype == np.asarray(v).dtype and got[k].shape == np.shape(v), k
        np.testing.assert_array_equal(got[k], v)


def test_damaged_member_is_refused(tmp_path):
    """The reader inflates members from the file's buffer itself: a damaged byte inside a
    member, an uncompressed (stored) file and a truncated one behave as with ``zipfile``."""
    from parse3d.assets.cache import _read_npz

    path = save_asset(registry.generate("cup", 0), tmp_path / "c.npz")
    with np.load(path, allow_pickle=False) as z:
        want = {k: z[k] for k in z.files}
    stored = tmp_path / "stored.npz"
    np.savez(stored, **want)  # no compression
    got = _read_npz(stored)
    assert all(np.array_equal(got[k], v) for k, v in want.items())
    raw = bytearray(path.read_bytes())
    with zipfile.ZipFile(path) as z:
        info = z.getinfo("p0_v.npy")
    raw[info.header_offset + 30 + len(info.filename) + info.compress_size // 2] ^= 0xFF
    bad = tmp_path / "bad.npz"
    bad.write_bytes(bytes(raw))
    with pytest.raises(AssetError, match=r"bad\.npz"):
        load_asset(bad)
    cut = tmp_path / "cut.npz"
    cut.write_bytes(path.read_bytes()[: len(raw) // 2])
    with pytest.raises(AssetError, match=r"cut\.npz"):
        load_asset(cut)
