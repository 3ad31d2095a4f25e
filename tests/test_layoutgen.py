"""Layout diffusion: data, encoders, network, training (determinism, resume, loss), sampling
into a scene folder, evaluation metrics and the CLI's input mistakes.

One tiny dataset (five solved and settled scenes of four objects) is built per module; the
networks are the ``tiny`` preset trained for a few dozen steps, so the file stays fast.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest

torch = pytest.importorskip("torch")  # the ml extra; make test installs it

from parse3d.assets.library import cache_dir  # noqa: E402
from parse3d.cli import main  # noqa: E402
from parse3d.datagen.build import BuildConfig, build_dataset, resolve_pag_paths  # noqa: E402
from parse3d.layoutgen import data, encoders, pose  # noqa: E402
from parse3d.layoutgen.evaluate import collisions, evaluate, layout_metrics, outside_room  # noqa: E402
from parse3d.layoutgen.sample import (  # noqa: E402
    SampleOptions,
    generate_poses,
    layout_scene,
    refine_layout,
    sample_layout,
    snap_proposals,
)
from parse3d.layoutgen.train import TrainConfig, load_run, train  # noqa: E402
from parse3d.pag.model import PAG  # noqa: E402
from parse3d.scene.io import read_scene, scene_schema  # noqa: E402


def _pag(name, relations, extra=()):
    objects = [("desk", "desk"), ("mug", "mug"), ("book", "book"), ("chair", "office_chair"),
               *extra]
    return {"format": "pag/1", "name": name,
            "room": {"type": "study", "footprint": [[0, 0], [3.5, 0], [3.5, 3], [0, 3]],
                     "height": 2.6},
            "objects": [{"id": i, "category": c} for i, c in objects], "relations": relations}


def _on(child, parent):
    return {"relation": "ON", "child": child, "parent": parent}


# the book stands beside the mug (written in a row; alone ON the top it would lie on its cover)
BASE = [_on("desk", "floor"), _on("mug", "desk:tabletop"), _on("book", "desk:tabletop"),
        {"relation": "SIDE_OF", "child": "book", "parent": "mug", "side": "right"},
        _on("chair", "floor")]
PAGS = [
    _pag("desk-wall", BASE + [{"relation": "AGAINST", "child": "desk:tabletop@back",
                               "parent": "wall_0"}]),
    _pag("desk-chair", BASE + [{"relation": "NEAR", "child": "chair", "parent": "desk",
                                "distance": 1.2},
                               {"relation": "TOWARD", "child": "chair", "parent": "desk"}]),
]


@pytest.fixture(scope="module", autouse=True)
def _one_thread():
    n = torch.get_num_threads()
    torch.set_num_threads(1)
    yield
    torch.set_num_threads(n)


@pytest.fixture(scope="module")
def dataset(tmp_path_factory) -> Path:
    pags = tmp_path_factory.mktemp("layout-pags")
    for p in PAGS:
        (pags / f"{p['name']}.json").write_text(json.dumps(p))
    out = tmp_path_factory.mktemp("layout-ds") / "ds"
    rep = build_dataset(BuildConfig(scenes=5, seed=3, source=resolve_pag_paths([pags])), out,
                        workers=1)
    assert rep.ok == 5
    return out


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory, dataset) -> Path:
    out = tmp_path_factory.mktemp("layout-run") / "pag"
    train(dataset, out, TrainConfig(steps=40, preset="tiny", relations="learned",
                                    checkpoint_every=20, noise_draws=8))
    return out


def test_pose_roundtrip():
    rng = np.random.default_rng(0)
    q, _ = np.linalg.qr(rng.normal(size=(5, 3, 3)))
    R = q * np.sign(np.linalg.det(q))[:, None, None]
    assert np.allclose(pose.rotation_from_6d(pose.rotation_to_6d(R)), R, atol=1e-9)
    fp = np.array([[0, 0], [4, 0], [4, 3], [0, 3]], float)
    p = np.c_[rng.uniform(0, 2.5, (5, 3)), rng.uniform(0.1, 1.5, (5, 3)), pose.rotation_to_6d(R)]
    st = pose.PoseStats.fit([p])
    x = pose.normalise_poses(p, fp, 2.5, st)
    assert np.abs(x[:, :3]).max() <= 1.0 + 1e-6 and x.dtype == np.float32
    # sizes within three standard deviations land inside the sampler's clipping range [-1, 1]
    assert np.abs(x[:, 3:6]).max() <= 1.0 and np.abs(x[:, 3:6]).max() > 0.2
    assert np.allclose(pose.denormalise_poses(x, fp, 2.5, st), p, atol=1e-5)


def test_dataset_graphs_and_split(dataset):
    scenes = data.load_dataset(dataset)
    assert len(scenes) == 5
    s = scenes[0]
    assert s.poses.shape == (4, 12) and s.categories[0] == "desk"
    # the settled pose of the desk, and its size is the scaled asset extents
    doc = json.loads((s.path / "scene.json").read_text())
    desk = next(o for o in doc["objects"] if o["id"] == "desk")
    assert np.allclose(s.poses[0, :3], desk["settled_pose"]["position"])
    assert np.allclose(s.poses[0, 3:6], desk["scale"] * s.assets[0].extents)
    kinds = {(r.relation, r.parent_category) for r in s.relations}
    assert ("ON", "desk") in kinds and ("ON", "floor") in kinds
    enc = encoders.ShapeDescriptor(["book", "desk", "mug", "office_chair"])
    g = data.graph_arrays(s.categories, s.assets, s.relations, s.footprint, s.height,
                          shape_encoder=enc, relation_encoder=encoders.TokenRelationEncoder(),
                          stats=pose.PoseStats.fit([s.poses]), poses=s.poses)
    assert g.shape.shape == (4, 1, enc.dim) and g.x0.shape == (4, 12)
    assert g.rel_vec.shape == (len(s.relations), encoders.TokenRelationEncoder().dim)
    assert g.room_geo[0, 0] == 1.0  # the desk stands on the floor
    split = data.split_scenes([x.scene_id for x in scenes], np.random.default_rng(1))
    ids = split["train"] + split["val"] + split["test"]
    assert sorted(ids) == sorted(x.scene_id for x in scenes) and len(split["test"]) == 1


def test_dataset_reads_asset_info_from_its_index(dataset, monkeypatch):
    """A second read takes extents and part labels from the index without loading an asset;
    an asset file that changed is read again; the assets themselves load on demand."""
    s = data.load_dataset(dataset)[0]
    index = data._INDEX.path
    assert index.is_file() and index.parent.parent == cache_dir()
    loaded = []
    real = data.load_asset_ref
    monkeypatch.setattr(data, "load_asset_ref", lambda ref: loaded.append(ref) or real(ref))
    data._INDEX.path = None  # read the index file again, as a new process would
    again = data.load_dataset(dataset)[0]
    assert loaded == [] and again.asset_info == s.asset_info and np.array_equal(again.poses, s.poses)
    a = again.assets[0]  # loaded on demand, and what the info says
    assert np.allclose(a.extents, again.asset_info[0].extents)
    assert again.asset_info[0].part_labels == tuple(p.label for p in a.parts)
    enc = encoders.ShapeDescriptor(s.categories)
    assert np.array_equal(enc.encode(a, s.categories[0]), enc.encode(s.asset_info[0], s.categories[0]))
    f = data._INDEX._file(dict(s.asset_info[0].ref))
    st = Path(f).stat()
    os.utime(f, ns=(st.st_atime_ns, st.st_mtime_ns + 1_000_000))
    loaded.clear()
    data.load_dataset(dataset)
    assert [r["id"] for r in loaded] == [s.asset_info[0].asset_id]


@pytest.mark.parametrize("frame", ["world", "parent"])
def test_sampling_recovers_the_poses_a_perfect_denoiser_knows(dataset, frame):
    """The sampler's half of the diffusion (scheduler steps, clipping, the epsilon-to-x0
    conversion, pose normalisation, 6-D rotations, the parent frame's composition): with the
    exact noise of a one-scene distribution as the network's answer, sampling must give that
    scene's poses back."""
    from parse3d.layoutgen.train import LayoutRun, make_scheduler

    ls = data.load_dataset(dataset)[0]
    stats = pose.PoseStats.fit([ls.poses])
    parents = data.support_parents(ls.relations, len(ls.categories)) if frame == "parent" else None
    if parents is not None:  # the mug and the book on the desk
        assert parents.tolist() == [-1, 0, 0, -1]
    x0 = torch.as_tensor(pose.normalise_poses(ls.poses, ls.footprint, ls.height, stats, parents))
    abar = make_scheduler().alphas_cumprod

    class Exact(torch.nn.Module):
        def __init__(self):
            super().__init__()
            self.anchor = torch.nn.Parameter(torch.zeros(1))  # device of the "network"

        def condition(self, g):
            return {}

        def forward(self, x_t, t, g, cond_mask, *, cond=None):
            a = abar[t.long()].to(x_t.dtype)[:, None, None]
            return (x_t - a.sqrt() * x0) / (1 - a).sqrt()

    run = LayoutRun(Path("exact"), TrainConfig(cond="pag", frame=frame), Exact(),
                    encoders.ShapeDescriptor(ls.categories), encoders.TokenRelationEncoder(),
                    stats, {}, "", 0)
    for steps in (100, 20):
        got = generate_poses(run, ls.categories, ls.asset_info, ls.relations, ls.footprint,
                             ls.height, seed=3, options=SampleOptions(steps=steps))
        assert np.abs(got[:, :6] - ls.poses[:, :6]).max() < 1e-4  # metres
        assert np.abs(got[:, 6:] - ls.poses[:, 6:]).max() < 1e-4


def test_parent_frame_follows_the_parent():
    """A supported object's parent-frame translation does not change when its parent and it
    move together (translated and turned); cycles and room parents give roots."""
    rng = np.random.default_rng(2)
    fp = np.array([[0, 0], [4, 0], [4, 3], [0, 3]], float)

    def yaw(a):
        return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1.0]])

    R = np.stack([yaw(a) for a in rng.uniform(-3, 3, 4)])
    p = np.c_[rng.uniform(0.5, 2.5, (4, 3)), rng.uniform(0.1, 1.5, (4, 3)), pose.rotation_to_6d(R)]
    parents = np.array([-1, 0, 1, -1])  # a tray on a desk, a cup on the tray
    st = pose.PoseStats.fit([p])
    x = pose.normalise_poses(p, fp, 2.5, st, parents)
    assert np.allclose(pose.denormalise_poses(x, fp, 2.5, st, parents), p, atol=1e-5)
    M, d = yaw(0.7), np.array([0.3, -0.2, 0.0])
    q = p.copy()
    q[:3, :3] = (p[:3, :3] - p[0, :3]) @ M.T + p[0, :3] + d
    q[:3, 6:] = pose.rotation_to_6d(M @ R[:3])
    y = pose.normalise_poses(q, fp, 2.5, st, parents)
    assert np.allclose(y[1:3, :3], x[1:3, :3], atol=1e-5)  # the tray and the cup
    assert not np.allclose(y[0, :3], x[0, :3])  # the desk moved
    rel = [encoders.RelationSpec(1, 0, "ON", "tray", "desk"),
           encoders.RelationSpec(0, 1, "ON", "desk", "tray"),  # would close a cycle
           encoders.RelationSpec(2, 1, "NEAR", "cup", "tray"),
           encoders.RelationSpec(2, -1, "ON", "cup", "floor"),
           encoders.RelationSpec(2, 0, "ON", "cup", "desk")]  # the cup's second support
    assert data.support_parents(rel, 3).tolist() == [-1, 0, -1]


def test_separation_pushes_boxes_apart():
    from parse3d.layoutgen.separate import box_push, separate_poses

    fp = np.array([[0, 0], [4, 0], [4, 3], [0, 3]], float)
    r6 = pose.rotation_to_6d(np.eye(3))
    p = np.array([np.r_[1.0, 1.5, 0, 1.0, 1.0, 1.0, r6],  # a cube ...
                  np.r_[1.6, 1.5, 0, 0.5, 0.5, 0.5, r6],  # ... and a smaller one 0.15 m into it
                  np.r_[1.0, 1.5, 0.98, 0.2, 0.2, 0.2, r6],  # sunk 2 cm into the first's top
                  np.r_[3.0, 1.5, 0, 1.0, 1.0, 1.0, r6],  # a shelf ...
                  np.r_[3.0, 1.5, 0.2, 0.3, 0.3, 0.3, r6]])  # ... and what is in it
    d = box_push(p, fp, 2.5)
    assert d[1, 0] > 0 and d[0, 0] < 0 and abs(d[1, 0]) > abs(d[0, 0])  # the smaller moves more
    assert d[2, 2] > 0 and np.allclose(d[2, :2], 0)  # lifted, not pushed sideways
    assert np.allclose(d[4], 0) and np.allclose(d[3], 0)  # inside the shelf: left alone
    q = separate_poses(p, fp, 2.5, rounds=12)
    assert q[1, 0] - 0.25 >= q[0, 0] + 0.5 - 0.01 and q[2, 2] >= 0.99
    assert np.all(q[:, 0] + 0.5 * q[:, 3] <= 4 + 1e-9)  # still in the room


def test_a_model_trained_on_one_scene_generates_it_back(dataset, tmp_path):
    """Training and sampling fit together (pose statistics, saved and loaded weights, the
    sampler): after a short training on one scene, the generated origins lie far closer to
    that scene's than random ones (bench_layout_overfit.py trains such runs longer)."""
    import shutil

    from parse3d.layoutgen.evaluate import random_poses

    one = tmp_path / "one"
    shutil.copytree(data.find_scenes(dataset)[0].parent, one / "s0")
    train(one, tmp_path / "run", TrainConfig(steps=150, preset="small", relations="learned",
                                              cond_dropout=0.0, checkpoint_every=150))
    run = load_run(tmp_path / "run")
    ls = data.load_dataset(one)[0]
    got = generate_poses(run, ls.categories, ls.asset_info, ls.relations, ls.footprint,
                         ls.height, seed=0, options=SampleOptions(steps=50))
    err = np.linalg.norm(got[:, :3] - ls.poses[:, :3], axis=1)
    rnd = np.linalg.norm(random_poses(ls, np.random.default_rng(0))[:, :3] - ls.poses[:, :3], axis=1)
    assert err.mean() < 0.25 * rnd.mean()  # 150 steps: about 0.27 m against 2 m


def test_text_relation_encoder_caches(tmp_path):
    r = encoders.RelationSpec(0, 1, "ON", "mug", "desk", None, "tabletop", None, None)
    near = encoders.RelationSpec(0, 1, "NEAR", "chair", "desk")
    cache = tmp_path / "rel.npz"
    v = encoders.TextRelationEncoder(cache).encode([r, near, r])
    assert v.shape == (3, 384) and np.allclose(np.linalg.norm(v, axis=1), 1, atol=1e-4)
    assert np.allclose(v[0], v[2]) and not np.allclose(v[0], v[1])
    assert encoders.relation_phrase(r) == "mug on desk tabletop"
    again = encoders.TextRelationEncoder(cache)  # from the cache, no model loaded
    assert np.allclose(again.encode([near]), v[1:2], rtol=1e-4, atol=1e-5) and again._model is None


def test_model_shapes_and_condition_matters():
    from parse3d.layoutgen.model import PRESETS, LayoutDenoiser, ModelConfig

    torch.manual_seed(0)
    m = LayoutDenoiser(ModelConfig(**PRESETS["tiny"], shape_dim=7, rel_dim=5))
    g = {"shape": torch.randn(3, 1, 7), "rel_vec": torch.randn(2, 5),
         "rel_child": torch.tensor([1, 2]), "rel_parent": torch.tensor([0, -1]),
         "room_geo": torch.zeros(3, 8), "room_ctx": torch.ones(4)}
    x, t = torch.randn(4, 3, 12), torch.tensor([0, 10, 500, 999])
    for p in m.parameters():  # zero-initialised modulations would hide the condition
        torch.nn.init.normal_(p, std=0.2)
    y1 = m(x, t, g, torch.ones(4))
    y0 = m(x, t, g, torch.zeros(4))
    assert y1.shape == (4, 3, 12) and torch.isfinite(y1).all()
    assert not torch.allclose(y1, y0)
    # with the condition dropped, nothing of the graph gets through (not even which pairs
    # carry a relation: the edge stream holds only those pairs)
    other = {**g, "rel_vec": torch.randn(3, 5), "rel_child": torch.tensor([0, 2, 1]),
             "rel_parent": torch.tensor([2, 1, -1])}
    scale = float(y0.abs().max())  # outputs reach tens: compare relative to their size
    assert torch.allclose(m(x, t, other, torch.zeros(4)), y0, rtol=1e-5, atol=1e-5 * scale)
    assert not torch.allclose(m(x, t, other, torch.ones(4)), y1)


def test_pair_relation_reaches_the_node_through_attention_values():
    """With the logits blind to edges and no node condition, which relation an object pair
    carries must still change the child's prediction (the attention-weighted edge values)."""
    from parse3d.layoutgen.model import PRESETS, LayoutDenoiser, ModelConfig

    torch.manual_seed(1)
    m = LayoutDenoiser(ModelConfig(**PRESETS["tiny"], shape_dim=7, rel_dim=5))
    for p in m.parameters():
        torch.nn.init.normal_(p, std=0.2)
    for blk in m.blocks:  # edges no longer touch logits; the node condition is not used
        torch.nn.init.zeros_(blk.e_mod.weight)
        torch.nn.init.zeros_(blk.e_mod.bias)
        torch.nn.init.zeros_(blk.film.weight)
        torch.nn.init.zeros_(blk.film.bias)
    base = {"shape": torch.randn(3, 1, 7), "rel_child": torch.tensor([1]),
            "rel_parent": torch.tensor([0]), "room_geo": torch.zeros(3, 8),
            "room_ctx": torch.ones(4)}
    x, t, keep = torch.randn(1, 3, 12), torch.tensor([10]), torch.ones(1)
    on = m(x, t, {**base, "rel_vec": torch.tensor([[1.0, 0, 0, 0, 0]])}, keep)
    near = m(x, t, {**base, "rel_vec": torch.tensor([[0.0, 0, 0, 0, 1]])}, keep)
    assert not torch.allclose(on[0, 1], near[0, 1], atol=1e-4)


def test_training_is_deterministic_resumes_and_learns(dataset, run_dir, tmp_path):
    cfg = TrainConfig(steps=6, preset="tiny", relations="learned", checkpoint_every=3,
                      noise_draws=8)
    a = train(dataset, tmp_path / "a", cfg)
    train(dataset, tmp_path / "b", TrainConfig(**{**cfg.__dict__, "steps": 3}))
    b2 = train(dataset, tmp_path / "b", cfg)  # resumes at step 3
    assert b2.start_step == 3 and a.losses == b2.losses
    wa = torch.load(tmp_path / "a" / "checkpoint.pt", weights_only=False)["ema"]
    wb = torch.load(tmp_path / "b" / "checkpoint.pt", weights_only=False)["ema"]
    assert all(torch.equal(x, y) for x, y in zip(wa["shadow_params"], wb["shadow_params"], strict=True))
    c = train(dataset, tmp_path / "c", TrainConfig(**{**cfg.__dict__, "seed": 1}))
    assert c.losses != a.losses
    # the run trained for 40 steps: the loss fell, files are where the docs say
    ck = torch.load(run_dir / "checkpoint.pt", weights_only=False)
    losses = ck["losses"]
    assert len(losses) == 40 and np.mean(losses[-10:]) < 0.8 * np.mean(losses[:5])
    for f in ("config.json", "split.json", "stats.json", "loss.png", "losses.csv"):
        assert (run_dir / f).is_file(), f
    assert len(ck["val_losses"]) == 2


def test_time_limit_stops_with_a_checkpoint(dataset, tmp_path):
    from parse3d.errors import InputError

    rep = train(dataset, tmp_path / "t", TrainConfig(steps=100_000, preset="tiny",
                                                     relations="learned", noise_draws=2,
                                                     time_limit=0.05))
    assert 0 < rep.steps < 100_000
    assert torch.load(tmp_path / "t" / "checkpoint.pt", weights_only=False)["step"] == rep.steps
    # --cpu-limit counts the process's CPU time (what it has used already included)
    from parse3d.layoutgen.train import _process_cpu

    limit = (_process_cpu() + 3.0) / 60.0
    rep = train(dataset, tmp_path / "c", TrainConfig(steps=100_000, preset="tiny",
                                                     relations="learned", noise_draws=2,
                                                     cpu_limit=limit))
    assert 0 < rep.steps < 100_000 and _process_cpu() >= 60.0 * limit
    assert torch.load(tmp_path / "c" / "checkpoint.pt", weights_only=False)["step"] == rep.steps
    with pytest.raises(InputError, match="--cpu-limit"):
        TrainConfig(cpu_limit=0).check()
    with pytest.raises(InputError, match="--cond pag"):
        TrainConfig(cond="none", frame="parent").check()


def test_sample_writes_a_scene(run_dir, tmp_path, capsys):
    import jsonschema

    run = load_run(run_dir)
    pag = PAG.from_dict(PAGS[1])
    s1 = sample_layout(run, pag, seed=4, options=SampleOptions(steps=10))
    s2 = sample_layout(run, pag, seed=4, options=SampleOptions(steps=10))
    assert [o.position.tolist() for o in s1.objects.values()] == \
        [o.position.tolist() for o in s2.objects.values()]
    out = tmp_path / "gen"
    main_rc = _rc(["layout", "sample", str(run_dir), "--pag", str(_write(tmp_path, PAGS[1])),
                   "--out", str(out), "--sample-steps", "10", "--seed", "4"])
    assert main_rc == 0
    doc = json.loads((out / "scene.json").read_text())
    jsonschema.validate(doc, scene_schema())
    sc = read_scene(out)
    assert set(sc.objects) == {"desk", "mug", "book", "chair"}
    assert (out / "scene.glb").stat().st_size > 1000
    for o in sc.objects.values():
        assert o.category == pag.objects[o.id].category and 0.25 <= o.scale <= 4.0
    assert np.allclose(sc.objects["desk"].position, s1.objects["desk"].position, atol=1e-5)
    # --refine: the solver starts from the generated poses and says how many it kept
    ref = tmp_path / "refined"
    assert _rc(["layout", "sample", str(run_dir), "--pag", str(_write(tmp_path, PAGS[1])),
                "--out", str(ref), "--sample-steps", "10", "--seed", "4", "--refine"]) == 0
    meta = json.loads((ref / "scene.json").read_text())["meta"]
    assert meta["refine"]["proposed"] == 4 and 0 <= meta["refine"]["kept"] <= 4
    assert len(meta["refine"]["kept_ids"]) == meta["refine"]["kept"]
    assert "solver kept" in capsys.readouterr().out


def test_metrics_see_collisions_and_the_room(dataset):
    ls = data.load_dataset(dataset)[0]
    pag = PAG.from_dict(json.loads((ls.path / "scene.json").read_text())["pag"])
    good = layout_scene(pag, ls.object_ids, ls.categories, ls.poses, seed=0, assets=ls.assets,
                        scales=list(ls.scales))
    assert collisions(good) == [] and outside_room(good) == []
    m = layout_metrics(good, physics=True)
    assert m.collision_rate == 0 and m.support_rate == 1.0 and m.relations == 1.0
    assert m.displacement < 0.02 and m.object_contacts >= 2
    assert m.stable >= 0.75  # a settled scene stays where it is (1 cm, 2 degrees)
    bad_poses = ls.poses.copy()
    bad_poses[3, :3] = bad_poses[0, :3]  # the chair inside the desk
    bad_poses[1, :2] = [-1.0, -1.0]  # the mug outside the room
    bad = layout_scene(pag, ls.object_ids, ls.categories, bad_poses, seed=0, assets=ls.assets,
                       scales=list(ls.scales))
    assert ("desk", "chair") in {(a, b) for a, b, _ in collisions(bad)}
    assert outside_room(bad) == ["mug"]
    mb = layout_metrics(bad, physics=False)
    assert mb.collision_rate == 0.5 and mb.outside == 0.25 and mb.support_rate < 1.0
    # separation on the meshes moves the smaller object (the chair) out of the desk
    from parse3d.layoutgen.separate import separate_scene

    desk = bad.objects["desk"].position.copy()
    assert separate_scene(bad) > 0
    assert collisions(bad) == [] and np.array_equal(bad.objects["desk"].position, desk)


def test_eval_rows(run_dir, dataset, tmp_path):
    run = load_run(run_dir)
    files = sorted((dataset / "scenes").glob("*/scene.json"))[:1]
    res = evaluate([run], files, seeds=2, physics=False, sample_steps=5, previews=0)
    names = [r.name for r in res.rows]
    assert names[:2] == ["solver (solved poses)", "random poses"]
    assert any(n.startswith("PAG-conditioned") for n in names)
    assert any("condition dropped" in n for n in names)
    solver = res.rows[0]
    assert solver.mean_std("collision_rate") == (0.0, 0.0)
    # the solver's own poses pass its own relation checks: the metric's upper bound is 1
    assert solver.mean_std("relations") == (1.0, 0.0)
    assert len(res.rows[1].per_seed) == 2
    assert "| solver (solved poses) |" in res.markdown()
    # separation guidance: every generated row, and the random poses get it as a row of their own
    # ... and with the relation-aware step: a row of its own after the PAG-conditioned one, on
    # the same samples, and a random control row
    sep = evaluate([run], files, seeds=1, physics=False, sample_steps=5, previews=0, separate=2,
                   fit=True)
    names = [r.name for r in sep.rows]
    assert names[2] == "random poses, separated"
    assert names[3] == "random poses, separated, relation-aware"
    assert all("separated 2" in n for n in names[4:]) and len(names) == 7
    assert names[5] == names[4][:-1] + ", relation-aware)"
    assert sep.rows[2].mean_std("collision_rate")[0] <= sep.rows[1].mean_std("collision_rate")[0]
    for r in sep.rows:  # the colliding pairs, by what they are to the PAG
        m = r.per_scene[0]
        assert m["colliding_pairs"] == sum(m[f"pairs_{k}"] for k in
                                           ("child_parent", "siblings", "floor", "other"))
    assert sep.rows[5].per_scene[0]["support_rate"] >= sep.rows[4].per_scene[0]["support_rate"]


def test_refine_keeps_the_solvers_own_poses(dataset):
    from parse3d.measure.checks import EPS

    ls = data.load_dataset(dataset)[1]
    doc = json.loads((ls.path / "scene.json").read_text())
    pag = PAG.from_dict(doc["pag"])
    solved = ls.poses if ls.solved_poses is None else ls.solved_poses
    # the solver's own layout as if generated, with the mug raised 3 cm and turned 10 degrees
    # off upright: snapping puts it back over the desk, upright, and the solver drops it
    poses = solved.copy()
    k = ls.object_ids.index("mug")
    a = np.deg2rad(10)
    tilt = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
    poses[k, 6:] = pose.rotation_to_6d(tilt @ pose.rotation_from_6d(poses[k, 6:]))
    poses[k, 2] += 0.03
    gen = layout_scene(pag, ls.object_ids, ls.categories, poses, seed=doc["seed"],
                       assets=ls.assets, scales=list(ls.scales))
    props = snap_proposals(pag, gen)
    assert set(props) == set(ls.object_ids)
    R, t = props["mug"]
    assert np.allclose(R[:, 2], [0, 0, 1]) and t[2] > solved[k, 2] + 0.005
    assert props["desk"][1][2] == pytest.approx(EPS)
    scene, rep = refine_layout(gen, seed=doc["seed"])
    assert rep.proposed == 4 and rep.placed == 4 and rep.failed == 0
    assert sorted(rep.kept) == sorted(ls.object_ids)  # every pose was good enough
    assert all(c.holds for c in scene.relations)
    assert abs(scene.objects["mug"].position[2] - solved[k, 2]) < 2e-3  # dropped back
    assert scene.meta["refine"]["kept"] == 4
    # a pose in the middle of another object is not kept: the solver samples instead
    bad = solved.copy()
    bad[ls.object_ids.index("chair"), :2] = solved[0, :2]
    gen2 = layout_scene(pag, ls.object_ids, ls.categories, bad, seed=doc["seed"],
                        assets=ls.assets, scales=list(ls.scales))
    scene2, rep2 = refine_layout(gen2, seed=doc["seed"])
    assert "chair" not in rep2.kept and scene2.objects["chair"].placed


def test_pointcloud_shape_encoder(dataset, tmp_path):
    from parse3d.layoutgen.pointcloud import PointCloudEncoder, surface_points, train_point_encoder

    scenes = data.load_dataset(dataset)
    assets = list({a.asset_id: a for s in scenes for a in s.assets}.values())
    p = surface_points(assets[0])
    assert p.shape == (256, 3) and np.abs(p).max() <= 0.5 + 1e-6
    assert np.array_equal(p, surface_points(assets[0]))
    state, losses = train_point_encoder(assets, steps=60, batch=8)
    assert np.mean(losses[-10:]) < 0.5 * np.mean(losses[:5])  # it learns to reconstruct
    enc = PointCloudEncoder(["book", "desk", "mug", "office_chair"], state)
    v = enc.encode(assets[0], scenes[0].categories[0])
    assert v.shape == (1, enc.dim) and enc.dim == 4 + 3 + 16
    codes = np.stack([enc.code(a) for a in assets])
    assert codes.std(0).max() > 1e-3  # different shapes, different codes
    enc.save(tmp_path)
    again = PointCloudEncoder.load(tmp_path, enc.config())
    assert np.allclose(again.encode(assets[0], scenes[0].categories[0]), v)
    # a run with the learned encoder trains, saves it and loads with it
    run = tmp_path / "pc"
    train(dataset, run, TrainConfig(steps=2, preset="tiny", relations="learned", shape="pointcloud",
                                    shape_steps=5, noise_draws=4))
    r = load_run(run)
    assert r.shape_encoder.name == "pointcloud" and (run / "shape_encoder.pt").is_file()
    assert sample_layout(r, PAG.from_dict(PAGS[0]), options=SampleOptions(steps=3)).objects


def _write(folder: Path, doc: dict) -> Path:
    p = folder / f"{doc['name']}.json"
    p.write_text(json.dumps(doc))
    return p


def _rc(argv) -> int:
    try:
        main(argv)
    except SystemExit as e:
        return int(e.code or 0)
    return 0


def test_cli_input_mistakes(run_dir, tmp_path, capsys):
    empty = tmp_path / "empty"
    empty.mkdir()
    assert _rc(["layout", "train", str(empty), "--out", str(tmp_path / "r")]) == 2
    assert "no scenes here" in capsys.readouterr().err
    odd = _pag("odd", BASE, extra=[("tub", "bathtub")])
    odd["relations"] = BASE + [_on("tub", "floor")]
    assert _rc(["layout", "sample", str(run_dir), "--pag", str(_write(tmp_path, odd)),
                "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "/objects/4/category" in err and "'bathtub' never seen in training" in err
    assert not (tmp_path / "o").exists()
    assert _rc(["layout", "sample", str(tmp_path / "nope"), "--pag",
                str(_write(tmp_path, PAGS[0])), "--out", str(tmp_path / "o")]) == 2
    assert "no checkpoint.pt here" in capsys.readouterr().err
    assert _rc(["layout", "train", str(empty), "--out", str(tmp_path / "r"), "--cond", "x"]) == 2
    assert "--cond" in capsys.readouterr().err


def test_relation_aware_fit_rests_children_and_parts_siblings(dataset):
    """The relation-aware step: an ON child sunk into its parent comes to rest on the parent's
    top, one floating off to the side comes back over it, siblings on one top end apart, and a
    desk AGAINST a wall comes to its gap, carrying what stands on it."""
    from parse3d.layoutgen.fit import GAP, fit_scene
    from parse3d.measure import check_relations

    ls = next(s for s in data.load_dataset(dataset) if s.pag.name.startswith("desk-wall"))
    pag = PAG.from_dict(json.loads((ls.path / "scene.json").read_text())["pag"])
    k = {o: i for i, o in enumerate(ls.object_ids)}
    p = (ls.poses if ls.solved_poses is None else ls.solved_poses).copy()
    p[[k["desk"], k["mug"], k["book"]], 1] += 0.04  # 4 cm off the wall (wall_0: y = 0)
    p[k["mug"], 2] -= 0.015  # 1.5 cm into the desk top
    p[k["book"], :2] = p[k["mug"], :2] + 0.02  # into the mug
    p[k["book"], 2] += 0.03  # and floating above the top
    wall = next(e for e in pag.relations if e.relation == "AGAINST")
    scene = layout_scene(pag, ls.object_ids, ls.categories, p, seed=0, assets=ls.assets,
                         scales=list(ls.scales))
    before = {a for a, b, _ in collisions(scene, depth=1e-3)} | \
        {b for a, b, _ in collisions(scene, depth=1e-3)}
    assert {"mug", "book"} <= before
    mug_xy = scene.objects["mug"].position[:2].copy()
    rep = fit_scene(scene)
    assert rep.contacts >= 4 and rep.pushed >= 1
    assert collisions(scene, depth=2e-3) == []
    top = scene.objects["desk"].world_bounds(settled=False)[1, 2]
    for oid in ("mug", "book"):
        low = scene.objects[oid].world_bounds(settled=False)[0, 2]
        assert abs(low - top) <= 2e-3, (oid, low - top)
    assert np.linalg.norm(scene.objects["mug"].position[:2] - mug_xy) < 0.3  # slid, not thrown
    scene.relations = check_relations(scene)
    held = {(c.relation, c.child): c.holds for c in scene.relations}
    assert held[("ON", "mug")] and held[("ON", "book")] and held[("ON", "desk")]
    assert held[(wall.relation, str(wall.child))]
    assert scene.objects["desk"].world_bounds(settled=False)[0, 1] < 0.04 - GAP  # back at it


def test_guidance_separates_collision_pieces_and_keeps_the_room(dataset):
    """One guidance pass set on real assets: a mug sunk 5 cm into the desk top is lifted onto
    it (not thrown off sideways), a chair driven into the desk comes out, a book half outside
    the room comes back in; an untouched, non-colliding layout does not move."""
    from parse3d.layoutgen.guide import guide_poses, guide_push, piece_boxes

    ls = next(s for s in data.load_dataset(dataset) if s.pag.name.startswith("desk-wall"))
    pag = PAG.from_dict(json.loads((ls.path / "scene.json").read_text())["pag"])
    k = {o: i for i, o in enumerate(ls.object_ids)}
    p = (ls.poses if ls.solved_poses is None else ls.solved_poses).copy()
    boxes = piece_boxes(ls.assets)
    assert np.abs(guide_push(p, boxes, ls.footprint, ls.height, ls.scales)).max() < 1e-9
    bad = p.copy()
    # the mug over the middle of the desk top (wherever the solver put it), sunk 5 cm into it
    solved = layout_scene(pag, ls.object_ids, ls.categories, p, seed=0, assets=ls.assets,
                          scales=list(ls.scales))
    desk_b, mug_b = (solved.objects[o].world_bounds(settled=False) for o in ("desk", "mug"))
    bad[k["mug"], :2] += (desk_b[0, :2] + desk_b[1, :2] - mug_b[0, :2] - mug_b[1, :2]) / 2
    bad[k["mug"], 2] -= 0.05
    bad[k["chair"], :2] = bad[k["desk"], :2] + [0.2, 0.1]
    bad[k["book"], :2] = [-0.1, 1.5]
    scene = layout_scene(pag, ls.object_ids, ls.categories, bad, seed=0, assets=ls.assets,
                         scales=list(ls.scales))
    hit = {x for a, b, _ in collisions(scene) for x in (a, b)}
    assert {"mug", "desk", "chair"} <= hit and outside_room(scene) == ["book"]
    got = guide_poses(bad, boxes, ls.footprint, ls.height, passes=16, scales=ls.scales)
    scene = layout_scene(pag, ls.object_ids, ls.categories, got, seed=0, assets=ls.assets,
                         scales=list(ls.scales))
    assert collisions(scene) == [] and outside_room(scene) == []
    assert np.allclose(got[k["mug"], :2], bad[k["mug"], :2], atol=1e-9)  # straight up
    top = scene.objects["desk"].world_bounds(settled=False)[1, 2]
    assert abs(scene.objects["mug"].world_bounds(settled=False)[0, 2] - top) < 0.01


def test_pag_guidance_lifts_children_onto_parents_and_parts_siblings_on_them(dataset):
    """The PAG-conditioned guidance on real assets: a mug and a book both sunk 4 cm into the
    desk top and into each other are lifted onto the top (not stacked: siblings part within
    their support surface, still over the desk), and the desk, pushed out of the chair,
    carries them along."""
    from parse3d.layoutgen.guide import guide_poses, pag_supports, piece_boxes

    ls = next(s for s in data.load_dataset(dataset) if s.pag.name.startswith("desk-wall"))
    pag = PAG.from_dict(json.loads((ls.path / "scene.json").read_text())["pag"])
    k = {o: i for i, o in enumerate(ls.object_ids)}
    sup = pag_supports(ls.relations, len(k))
    assert sup[k["mug"]] == k["desk"] and sup[k["book"]] == k["desk"] and sup[k["desk"]] == -1
    p = (ls.poses if ls.solved_poses is None else ls.solved_poses).copy()
    bad = p.copy()
    bad[k["mug"], 2] -= 0.04
    bad[k["book"], :2] = bad[k["mug"], :2] + [0.02, 0.0]
    bad[k["book"], 2] = bad[k["mug"], 2] + 0.01
    boxes = piece_boxes(ls.assets)
    got = guide_poses(bad, boxes, ls.footprint, ls.height, passes=16, scales=ls.scales,
                      supports=sup)
    scene = layout_scene(pag, ls.object_ids, ls.categories, got, seed=0, assets=ls.assets,
                         scales=list(ls.scales))
    assert collisions(scene) == [] and outside_room(scene) == []
    desk = scene.objects["desk"].world_bounds(settled=False)
    for oid in ("mug", "book"):
        b = scene.objects[oid].world_bounds(settled=False)
        assert abs(b[0, 2] - desk[1, 2]) < 0.01, oid  # on the top, not on each other
        c = b.mean(0)[:2]
        assert (desk[0, :2] <= c).all() and (c <= desk[1, :2]).all(), oid  # over the desk
    # the chair driven into the desk: the desk moves out of it with what it carries
    bad = p.copy()
    bad[[k["desk"], k["mug"], k["book"]], 1] += 0.5  # off the wall, free to move
    bad[k["chair"], :2] = bad[k["desk"], :2] + [0.2, 0.1]
    got = guide_poses(bad, boxes, ls.footprint, ls.height, passes=16, scales=ls.scales,
                      supports=sup)
    moved = got[:, :3] - bad[:, :3]
    assert np.abs(moved[k["desk"]]).max() > 1e-3
    assert np.allclose(moved[k["mug"]], moved[k["desk"]]) and \
        np.allclose(moved[k["book"]], moved[k["desk"]])

def test_guided_sampling_ends_on_the_guided_estimate(dataset):
    """Guidance inside the sampler: a 'network' that knows one colliding layout exactly gives
    it back without guidance and a layout without collisions with it (the noise estimate is
    made consistent with the moved estimate, so the last step returns the moved layout)."""
    from parse3d.layoutgen.train import LayoutRun, make_scheduler

    ls = next(s for s in data.load_dataset(dataset) if s.pag.name.startswith("desk-wall"))
    pag = PAG.from_dict(json.loads((ls.path / "scene.json").read_text())["pag"])
    k = {o: i for i, o in enumerate(ls.object_ids)}
    bad = ls.poses.copy()
    bad[k["chair"], :2] = bad[k["desk"], :2] + [0.15, 0.0]  # the chair in the desk
    stats = pose.PoseStats.fit([ls.poses])
    x0 = torch.as_tensor(pose.normalise_poses(bad, ls.footprint, ls.height, stats))
    abar = make_scheduler().alphas_cumprod

    class Exact(torch.nn.Module):
        def __init__(self):
            super().__init__()
            self.anchor = torch.nn.Parameter(torch.zeros(1))

        def condition(self, g):
            return {}

        def forward(self, x_t, t, g, cond_mask, *, cond=None):
            a = abar[t.long()].to(x_t.dtype)[:, None, None]
            return (x_t - a.sqrt() * x0) / (1 - a).sqrt()

    run = LayoutRun(Path("exact"), TrainConfig(cond="pag"), Exact(),
                    encoders.ShapeDescriptor(ls.categories), encoders.TokenRelationEncoder(),
                    stats, {}, "", 0)

    def sampled(guide):
        got = generate_poses(run, ls.categories, ls.assets, ls.relations, ls.footprint,
                             ls.height, seed=1, options=SampleOptions(steps=10, guide=guide))
        return got, layout_scene(pag, ls.object_ids, ls.categories, got, seed=0,
                                 assets=ls.assets, scales=list(ls.scales))

    plain, scene = sampled(0)
    assert np.abs(plain[:, :3] - bad[:, :3]).max() < 1e-4
    assert ("desk", "chair") in {(a, b) for a, b, _ in collisions(scene)}
    guided, scene = sampled(2)
    assert collisions(scene) == [] and outside_room(scene) == []
    assert np.abs(guided[:, 3:] - plain[:, 3:]).max() < 1e-4  # only translations move


def test_eval_with_guidance_has_a_random_control_row(run_dir, dataset, tmp_path):
    run = load_run(run_dir)
    files = sorted((dataset / "scenes").glob("*/scene.json"))[:1]
    res = evaluate([run], files, seeds=1, physics=False, sample_steps=5, previews=0, guide=2)
    names = [r.name for r in res.rows]
    assert names[:3] == ["solver (solved poses)", "random poses", "random poses, guided (control)"]
    assert all(n.endswith("guided 2)") for n in names[3:]) and len(names) == 5
    assert res.rows[2].mean_std("outside")[0] == 0.0
    for r in res.rows[3:]:
        assert r.mean_std("outside")[0] == 0.0
    # the CLI: a guided sample places the assets the guidance saw, inside the room
    out = tmp_path / "guided"
    assert _rc(["layout", "sample", str(run_dir), "--pag", str(_write(tmp_path, PAGS[1])),
                "--out", str(out), "--sample-steps", "5", "--guide", "2"]) == 0
    sc = read_scene(out)
    assert sc.meta["guide"] == 2 and outside_room(sc) == []


class _Marker:
    """Unpickling this calls ``os.mkdir('pwned')``: what a crafted checkpoint would run."""

    def __reduce__(self):
        return (os.mkdir, ("pwned",))


def test_a_crafted_checkpoint_runs_no_code_and_damaged_runs_exit_2(run_dir, tmp_path, capsys,
                                                                   monkeypatch):
    import shutil

    monkeypatch.chdir(tmp_path)
    pag = str(_write(tmp_path, PAGS[0]))

    def copy(name: str) -> Path:
        d = tmp_path / name
        shutil.copytree(run_dir, d)
        return d

    def sample(run: Path) -> tuple[int, str]:
        rc = _rc(["layout", "sample", str(run), "--pag", pag, "--out", str(tmp_path / "o")])
        return rc, capsys.readouterr().err

    # the crafted file is a real exploit: the unsafe loader runs it
    evil = copy("evil")
    ck = torch.load(evil / "checkpoint.pt", weights_only=True)
    ck["step"] = _Marker()
    torch.save(ck, evil / "checkpoint.pt")
    torch.load(evil / "checkpoint.pt", weights_only=False)
    assert (tmp_path / "pwned").is_dir()
    (tmp_path / "pwned").rmdir()
    for argv in (["layout", "sample", str(evil), "--pag", pag, "--out", str(tmp_path / "o")],
                 ["layout", "eval", str(evil), "--out", str(tmp_path / "e")],
                 ["layout", "train", "nowhere", "--out", str(evil)]):
        assert _rc(argv) == 2
        assert not (tmp_path / "pwned").exists()
    assert "checkpoint.pt" in capsys.readouterr().err

    def damaged(name: str, file: str, change) -> None:
        d = copy(name)
        change(d / file)
        rc, err = sample(d)
        assert rc == 2, err
        assert str(d / file) in err and "Traceback" not in err
        assert not (tmp_path / "o").exists()

    damaged("truncated", "checkpoint.pt", lambda p: p.write_bytes(p.read_bytes()[:1000]))
    damaged("random", "checkpoint.pt", lambda p: p.write_bytes(os.urandom(5000)))

    def no_ema(p):
        ck = torch.load(p, weights_only=True)
        del ck["ema"]
        torch.save(ck, p)

    damaged("no-ema", "checkpoint.pt", no_ema)
    damaged("half-config", "config.json", lambda p: p.write_text(p.read_text()[:200]))

    def unknown_key(p):
        doc = json.loads(p.read_text())
        doc["train"]["surprise"] = 1
        p.write_text(json.dumps(doc))

    damaged("unknown-key", "config.json", unknown_key)
    damaged("stats", "stats.json", lambda p: p.write_text('{"log_size_mean": 3}'))
    damaged("split", "split.json", lambda p: p.write_text("[1, 2]"))
