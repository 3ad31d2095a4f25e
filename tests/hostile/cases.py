"""The hostile corpus: inputs, folders and environments a careful new user may throw at every
command, with the exit code and the words the answer must contain.

A case is a dict:

``id``        folder name of the case (its working folder while it runs)
``argv``      the ``parse3d`` arguments
``code``      expected exit code
``words``     words the combined stdout+stderr must contain (case-insensitive)
``files``     relative path -> text, bytes, or a special: ``@fifo``, ``@dir``, ``@link:TARGET``
``outputs``   relative paths the case may create or change (nothing else may change)
``env``       environment overrides; ``{case}`` in a value is the case folder
``block``     modules made unimportable for the case (a missing optional extra)
``absent`` / ``present``  relative paths that must not / must exist afterwards
``group``     cases of one group share a process (default ``main``)

Placeholders in file texts: ``{hostname}``.
"""

from __future__ import annotations

import json
import os
import pickle
from pathlib import Path

DATA = Path(__file__).parent / "data"
TINY = (DATA / "tiny.json").read_text()
SCENE = json.loads((DATA / "scene.json").read_text())


def pag(**over) -> dict:
    d = json.loads(TINY)
    d.update(over)
    return d


def one_object(name: str = "one") -> dict:
    return {"format": "pag/1", "name": name,
            "room": {"type": "study", "footprint": [[0, 0], [3, 0], [3, 3], [0, 3]], "height": 2.5},
            "objects": [{"id": "box", "category": "storage_box"}],
            "relations": [{"relation": "ON", "child": "box", "parent": "floor"}]}


def chain(n: int) -> dict:
    """A PAG of n boxes, each ON the previous one (a support chain n deep)."""
    objs = [{"id": f"b{i}", "category": "storage_box"} for i in range(n)]
    rels = [{"relation": "ON", "child": "b0", "parent": "floor"}] + [
        {"relation": "ON", "child": f"b{i}", "parent": f"b{i - 1}"} for i in range(1, n)]
    return {"format": "pag/1", "name": "chain",
            "room": {"type": "study", "footprint": [[0, 0], [3, 0], [3, 3], [0, 3]], "height": 2.5},
            "objects": objs, "relations": rels}


def scene(mut=None) -> str:
    d = json.loads(json.dumps(SCENE))
    if mut is not None:
        mut(d)
    return json.dumps(d, indent=1)


def _set(path: list, value):
    def f(d):
        x = d
        for k in path[:-1]:
            x = x[k]
        x[path[-1]] = value
    return f


def _pop(path: list):
    def f(d):
        x = d
        for k in path[:-1]:
            x = x[k]
        del x[path[-1]]
    return f


J = json.dumps
BOMB = "a: &a [x, x, x, x, x, x, x, x, x]\n" + "".join(
    f"{c}: &{c} [{', '.join(['*' + p] * 9)}]\n" for p, c in zip("abcdefgh", "bcdefghi", strict=True))
DEEP_JSON = "[" * 100_000 + "]" * 100_000
DEEP_YAML = "a:\n" + "".join("  " * i + "- \n" for i in range(1, 300))
TEMPLATE = """format: pag-template/1
name: big
room_type: study
room: {width: 4, depth: 4, height: 2.7}
objects:
  - {id: box, category: storage_box, count: COUNT}
relations:
  - {relation: ON, child: box, parent: floor}
"""
CIRCLE = [[round(5 + 4 * __import__("math").cos(2 * __import__("math").pi * k / 300), 4),
           round(5 + 4 * __import__("math").sin(2 * __import__("math").pi * k / 300), 4)]
          for k in range(300)]
class _Marker:
    """Unpickling this calls ``os.mkdir('pwned')`` in the case folder: a crafted model file."""

    def __reduce__(self):
        return (os.mkdir, ("pwned",))


CRAFTED = pickle.dumps({"model": _Marker(), "ema": {}, "step": 1})
RUN_CONFIG = J({"format": "parse3d-layout-run/1", "train": {"preset": "tiny",
                                                             "relations": "learned"},
                "shape_encoder": {"name": "descriptor", "categories": ["desk", "book"]},
                "relation_encoder": "learned", "dataset": "ds"})


def run_files(**over) -> dict:
    """A layout run folder ``run/`` (config, stats, split) with ``over`` replacing files."""
    files = {"run/config.json": RUN_CONFIG, "run/checkpoint.pt": CRAFTED,
             "run/stats.json": J({"log_size_mean": [0, 0, 0], "log_size_std": [1, 1, 1]}),
             "run/split.json": J({"train": [], "val": [], "test": []}), "p.json": TINY}
    files.update({f"run/{k}": v for k, v in over.items()})
    return files


SGG_GT = J({"id": "s1", "task": "sgg", "meta": {
    "objects": [{"name": "mug#1", "label": "mug", "box": [10, 10, 50, 50]}],
    "triplets": []}}) + "\n"
SETTLE = ["settle", "scene"]
SCENE_FILES = {"scene/scene.json": scene()}
DS = ["dataset", "build", "--scenes", "1", "--no-settle", "--out"]


def _cases() -> list[dict]:
    c: list[dict] = []

    def add(id, argv, code, words=(), **kw):
        c.append({"id": id, "argv": argv, "code": code, "words": list(words), **kw})

    # ---------------------------------------------------------------- 2. parsers
    add("json-deep", ["validate", "p.json"], 2, ["nested"], files={"p.json": DEEP_JSON})
    add("yaml-deep", ["validate", "p.yaml"], 2, ["nested"], files={"p.yaml": DEEP_YAML})
    add("yaml-flow-deep", ["validate", "p.yaml"], 2, ["nested"],
        files={"p.yaml": "[" * 50_000 + "]" * 50_000})
    add("yaml-alias-bomb", ["validate", "p.yaml"], 2, ["aliases"], files={"p.yaml": BOMB})
    add("yaml-timestamp", ["validate", "p.yaml"], 2, ["!!timestamp", "/name"],
        files={"p.yaml": "format: pag/1\nname: !!timestamp 2024-01-02\n"})
    add("yaml-set", ["validate", "p.yaml"], 2, ["!!set", "/meta"],
        files={"p.yaml": "format: pag/1\nmeta: !!set {a, b}\n"})
    add("yaml-binary", ["validate", "p.yaml"], 2, ["!!binary"],
        files={"p.yaml": "format: pag/1\nname: !!binary aGVsbG8=\n"})
    add("yaml-python-tag", ["validate", "p.yaml"], 2, ["tag"],
        files={"p.yaml": "format: pag/1\nname: !!python/object:os.system [ls]\n"})
    add("yaml-dup-key", ["validate", "p.yaml"], 2, ["repeated", "/name"],
        files={"p.yaml": "format: pag/1\nname: a\nname: b\n"})
    add("json-dup-key", ["validate", "p.json"], 2, ["repeated", "/name"],
        files={"p.json": TINY.replace('"name": "tiny"', '"name": "a", "name": "b"')})
    add("json-dup-nested", ["validate", "p.json"], 2, ["repeated", "/room/height"],
        files={"p.json": TINY.replace('"height": 2.5', '"height": 2.5, "height": 3')})
    add("json-nan", ["validate", "p.json"], 2, ["NaN"],
        files={"p.json": TINY.replace('"height": 2.5', '"height": NaN')})
    add("json-huge-number", ["validate", "p.json"], 2, ["finite"],
        files={"p.json": TINY.replace('"height": 2.5', '"height": 1e400')})
    add("yaml-inf", ["validate", "p.yaml"], 2, ["finite", "/room/height"],
        files={"p.yaml": "format: pag/1\nroom: {height: .inf}\n"})
    add("fifo-input", ["validate", "p.json"], 2, ["not a regular file"], files={"p.json": "@fifo"})
    add("device-input", ["validate", "zero.json"], 2, ["not a regular file"],
        files={"zero.json": "@link:/dev/zero"})
    add("dir-input", ["validate", "d.json"], 2, ["folder"], files={"d.json": "@dir"})
    add("fifo-pag-show", ["pag", "show", "p.yaml"], 2, ["not a regular file"],
        files={"p.yaml": "@fifo"})
    add("not-utf8", ["validate", "p.json"], 2, ["UTF-8"], files={"p.json": b"{\"name\": \"\xff\xfe\"}"})
    add("empty-json", ["validate", "p.json"], 2, ["invalid JSON"], files={"p.json": ""})
    add("json-list", ["validate", "p.json"], 2, ["p.json"], files={"p.json": "[1, 2]"})
    add("unknown-ext", ["validate", "p.txt"], 2, ["unknown file type"], files={"p.txt": TINY})
    add("missing-file", ["validate", "nope.json"], 2, ["no such file"])
    add("yaml-complex-key", ["validate", "p.yaml"], 2, ["key"], files={"p.yaml": "? [a, b]\n: c\n"})

    # ---------------------------------------------------------------- 3. bounds in PAGs
    add("footprint-1e300", ["validate", "p.json"], 2, ["/room/footprint", "origin"],
        files={"p.json": J(pag(room={"type": "study", "height": 2.5, "footprint":
                                     [[0, 0], [1e300, 0], [1e300, 1e300], [0, 1e300]]}))})
    add("footprint-2km", ["validate", "p.json"], 2, ["1000 m square"],
        files={"p.json": J(pag(room={"type": "study", "height": 2.5, "footprint":
                                     [[0, 0], [2000, 0], [2000, 3], [0, 3]]}))})
    add("footprint-300-walls", ["validate", "p.json"], 2, ["at most 256"],
        files={"p.json": J(pag(room={"type": "study", "height": 2.5, "footprint": CIRCLE}))})
    add("height-huge", ["validate", "p.json"], 2, ["/room/height"],
        files={"p.json": J(pag(room={"type": "study", "height": 1e9, "footprint":
                                     [[0, 0], [3, 0], [3, 3], [0, 3]]}))})
    add("scale-1e300", ["validate", "p.json"], 2, ["/objects/0/scale"],
        files={"p.json": J(pag(objects=[{"id": "desk", "category": "desk",
                                         "scale": [1e300, 1e300]},
                                        {"id": "book", "category": "book"}]))})
    add("scale-zero", ["validate", "p.json"], 2, ["/objects/0/scale", "positive"],
        files={"p.json": J(pag(objects=[{"id": "desk", "category": "desk", "scale": [0, 1]},
                                        {"id": "book", "category": "book"}]))})
    add("too-many-objects", ["validate", "--no-vocabulary", "p.json"], 2, ["at most 1000"],
        files={"p.json": J(chain(1001))})
    add("long-id", ["validate", "p.json"], 2, ["at most 100"],
        files={"p.json": TINY.replace('"book"', '"' + "b" * 200 + '"')})
    add("param-out-of-range", ["validate", "p.json"], 2, ["out of range"],
        files={"p.json": J(pag(relations=pag()["relations"] + [
            {"relation": "NEAR", "child": "book", "parent": "desk", "distance": 1e9}]))})

    # ---------------------------------------------------------------- pag draw/show
    add("draw-too-many", ["pag", "draw", "--no-vocabulary", "p.json", "-o", "g.png"], 2,
        ["too many"], files={"p.json": J(chain(400))})
    add("draw-too-deep", ["pag", "draw", "--no-vocabulary", "p.json", "-o", "g.png"], 2,
        ["too deep"], files={"p.json": J(chain(60))})
    add("draw-bad-ext", ["pag", "draw", "p.json", "-o", "g.txt"], 2, [".png"],
        files={"p.json": TINY})
    add("draw-out-is-dir", ["pag", "draw", "p.json", "-o", "g.png"], 2, ["g.png"],
        files={"p.json": TINY, "g.png": "@dir"})

    # ---------------------------------------------------------------- solve / generate
    add("solve-seed-negative", ["solve", "p.json", "--seed", "-1"], 2, ["--seed"],
        files={"p.json": TINY})
    add("solve-seed-huge", ["solve", "p.json", "--seed", str(2**40)], 2, ["--seed"],
        files={"p.json": TINY})
    add("solve-out-is-file", ["solve", "p.json", "--out", "f"], 2, ["file"],
        files={"p.json": TINY, "f": "keep"})
    add("solve-out-under-file", ["solve", "p.json", "--out", "f/sub"], 2, ["file"],
        files={"p.json": TINY, "f": "keep"})
    add("solve-bad-strategy", ["solve", "p.json", "--strategy", "magic", "--out", "o"], 2,
        ["strategy"], files={"p.json": TINY})
    add("solve-invalid-pag", ["solve", "p.json"], 2, ["no supporter"],
        files={"p.json": J(pag(relations=[]))})
    add("name-escapes", ["solve", "p.json", "--no-settle", "--no-preview"], 0, ["placed"],
        files={"p.json": J(one_object("../../escaped"))}, outputs=["out"],
        present=["out/escaped-0/scene.json"])
    add("name-nul-long", ["solve", "p.json", "--no-settle", "--no-preview"], 0, ["placed"],
        files={"p.json": J(one_object("a\u0000/" + "x" * 300))}, outputs=["out"],
        present=["out/a_" + "x" * 98 + "-0/scene.json"])
    add("stale-outputs", ["solve", "p.json", "--no-settle", "--no-preview", "--out", "o"], 0,
        ["placed"], files={"p.json": J(one_object()), "o/contacts.json": "[]",
                           "o/scene.json": scene(),
                           "o/preview.png": "old", "o/rgb_0.png": "old", "o/views.json": "{}",
                           "o/notes.txt": "mine"},
        outputs=["o/scene.json", "o/scene.glb", "o/exports.json", "o/contacts.json",
                 "o/preview.png",
                 "o/rgb_0.png", "o/views.json"],
        absent=["o/contacts.json", "o/preview.png", "o/rgb_0.png", "o/views.json"],
        present=["o/notes.txt", "o/scene.json"])
    add("solve-foreign-scene-json", ["solve", "p.json", "--out", "o"], 2, ["not a parse3d"],
        files={"p.json": J(one_object()), "o/scene.json": '{"mine": true}',
               "o/preview.png": "mine"})
    add("generate-unknown-room", ["generate", "spaceship"], 2, ["room type"])
    add("generate-seed-negative", ["generate", "bedroom", "--seed", "-5"], 2, ["--seed"])

    # ---------------------------------------------------------------- settle bounds
    for opt, val, word in (("--threshold", "inf", "--threshold"),
                           ("--threshold", "nan", "--threshold"),
                           ("--threshold", "0", "--threshold"),
                           ("--dt", "inf", "--dt"), ("--dt", "0", "--dt"),
                           ("--dt", "-0.01", "--dt"),
                           ("--linear-damping", "-1", "--linear-damping"),
                           ("--angular-damping", "nan", "--angular-damping"),
                           ("--steps", "0", "--steps"), ("--steps", "1000000000", "--steps")):
        add(f"settle{opt}-{val}", SETTLE + [opt, val], 2, [word], files=SCENE_FILES)

    # ---------------------------------------------------------------- 6. damaged scenes
    def bad_scene(id, text, words, cmd=("settle",)):
        add(id, [*cmd, "scene"], 2, words, files={"scene/scene.json": text})

    bad_scene("scene-missing-pose", scene(_pop(["objects", 0, "pose"])), ["/objects/0/pose"])
    bad_scene("scene-objects-object", scene(_set(["objects"], {"desk": 1})), ["/objects"])
    bad_scene("scene-nan", scene().replace('"scale": 1.0', '"scale": NaN', 1), ["NaN"])
    bad_scene("scene-null-position", scene(_set(["objects", 0, "pose", "position"],
                                                [None, 1, 2])), ["/objects/0/pose/position"])
    bad_scene("scene-zero-quaternion", scene(_set(["objects", 0, "pose", "quaternion"],
                                                  [0, 0, 0, 0])), ["quaternion"])
    bad_scene("scene-unknown-category", scene(_set(["objects", 0, "asset", "category"],
                                                   "spaceship")), ["unknown asset category"])
    bad_scene("scene-degenerate-room", scene(_set(["pag", "room", "footprint"],
                                                  [[0, 0], [1, 0], [2, 0]])),
              ["/pag/room/footprint"])
    bad_scene("scene-truncated", scene()[:500], ["invalid JSON"])
    bad_scene("scene-wrong-format", scene(_set(["format"], "something/9")), ["format"])
    bad_scene("scene-list", "[]", ["object"])
    bad_scene("scene-render-missing-key", scene(_pop(["pag"])), ["/pag"], cmd=("render",))
    bad_scene("scene-render-bad-scale", scene(_set(["objects", 1, "scale"], -2)),
              ["/objects/1/scale"], cmd=("render",))
    add("scene-fifo", SETTLE, 2, ["not a regular file"], files={"scene/scene.json": "@fifo"})
    add("scene-missing", SETTLE, 2, ["no scene.json"], files={"scene/x": "x"})
    add("contacts-damaged", ["render", "scene"], 2, ["contacts.json", "/0/min_distance"],
        files={"scene/scene.json": scene(_set(["summary", "contacts"], 1)),
               "scene/contacts.json": '[{"a": "x:y", "b": "z:w", "samples": 1}]'})

    # ---------------------------------------------------------------- render bounds
    for id, args, word in (("render-views-negative", ["--views", "-1"], "--views"),
                           ("render-views-huge", ["--views", "5000"], "--views"),
                           ("render-size-zero", ["--size", "0x0"], "--size"),
                           ("render-size-huge", ["--size", "100000x10"], "--size"),
                           ("render-seed-negative", ["--seed", "-1"], "--seed")):
        add(id, ["render", "scene", *args], 2, [word], files=SCENE_FILES)
    add("render-missing-folder", ["render", "nowhere"], 2, ["no scene.json"])

    # ---------------------------------------------------------------- 9. templates
    add("template-count-huge", ["template", "expand", "t.yaml"], 2, ["at most 100"],
        files={"t.yaml": TEMPLATE.replace("COUNT", "100000000").replace("name: big",
                                                                          "name: t")})
    add("template-count-range-huge", ["template", "expand", "t.yaml"], 2, ["at most 100"],
        files={"t.yaml": TEMPLATE.replace("COUNT", "[1, 1000000]").replace("name: big",
                                                                             "name: t")})
    add("template-bomb", ["template", "expand", "t.yaml"], 2, ["aliases"],
        files={"t.yaml": BOMB})
    add("template-unknown", ["template", "expand", "no-such-template"], 2, ["no template"])
    add("template-seed-negative", ["template", "expand", "bedroom-master-01", "--seed", "-1"],
        2, ["--seed"])
    add("template-check-seeds-huge", ["template", "check", "bedroom-master-01", "--seeds",
                                      "100000"], 2, ["--seeds"])
    add("template-out-is-dir", ["template", "expand", "bedroom-master-01", "-o", "o.json"], 2,
        ["o.json"], files={"o.json": "@dir"})
    add("template-list-unknown-room", ["template", "list", "--room-type", "spaceship"], 2,
        ["room type"])

    # ---------------------------------------------------------------- 1, 11. datasets
    user = {"d/scenes/mine.txt": "precious", "d/.tmp-x/notes.txt": "precious",
            "d/notes.md": "mine"}
    add("dataset-not-a-dataset", DS + ["d"], 2, ["not empty", "nothing was changed"],
        files=user)
    add("dataset-out-is-file", DS + ["f"], 2, ["file"], files={"f": "keep"})
    add("dataset-locked", DS + ["d"], 2, ["another process", "pid 1"],
        files={"d/.parse3d-build.lock": '{"pid": 1, "host": "{hostname}"}'})
    add("dataset-other-settings", DS + ["d"], 2, ["other settings"],
        files={"d/dataset.json": J({"format": "parse3d-dataset/1", "scenes": 1, "seed": 7,
                                    "rooms": [], "views": 0, "view_size": [640, 480],
                                    "settle": False, "source": {"kind": "templates"},
                                    "time_limit": 600.0})})
    add("dataset-foreign-scene-folder", DS + ["d", "--rooms", "bedroom"], 2,
        ["not written by the dataset builder"],
        files={"d/dataset.json": J({"format": "parse3d-dataset/1", "scenes": 1, "seed": 0,
                                    "rooms": ["bedroom"], "views": 0, "view_size": [640, 480],
                                    "settle": False, "source": {"kind": "templates"},
                                    "time_limit": 600.0}),
               "d/scenes/00000/mine.txt": "precious"},
        outputs=["d/dataset.json", "d/.parse3d-build.lock", "d/.parse3d-journal"])
    add("dataset-no-pyarrow", DS + ["new"], 2, ["parse3d[dataset]"], block=["pyarrow"],
        absent=["new"])
    for id, args, word in (("dataset-scenes-negative", ["--scenes", "-1"], "--scenes"),
                           ("dataset-scenes-huge", ["--scenes", str(10**9)], "--scenes"),
                           ("dataset-time-limit-inf", ["--time-limit", "inf"], "--time-limit"),
                           ("dataset-time-limit-nan", ["--time-limit", "nan"], "--time-limit"),
                           ("dataset-views-huge", ["--views", "1000"], "--views"),
                           ("dataset-workers-zero", ["--workers", "0"], "--workers"),
                           ("dataset-seed-negative", ["--seed", "-1"], "--seed"),
                           ("dataset-unknown-room", ["--rooms", "spaceship"], "room type"),
                           ("dataset-size-zero", ["--size", "0x1"], "--size")):
        add(id, ["dataset", "build", "--out", "new", "--no-settle", "--scenes", "1", *args], 2,
            [word],
            absent=["new"])

    add("dataset-stats-damaged-manifest", ["dataset", "stats", "d"], 2, ["manifest"],
        files={"d/manifest.parquet": "garbage", "d/dataset.json": "{}"})
    add("dataset-stats-damaged-config", ["dataset", "stats", "d"], 2, ["dataset.json"],
        files={"d/manifest.parquet": "@manifest", "d/dataset.json": "{"})
    add("dataset-stats-not-a-dataset", ["dataset", "stats", "d"], 2, ["no manifest"],
        files={"d/x.txt": "x"})

    # ---------------------------------------------------------------- 10. assets
    add("assets-placeholder-labels", ["assets", "add", "src", "--category", "thing"], 2,
        ["placeholder"], files={"src/a.glb": "@glb:node_0,geometry"})
    add("assets-label-not-identifier", ["assets", "add", "src", "--category", "thing",
                                        "--mapping", "m.json"], 2, ["not an identifier"],
        files={"src/a.glb": "@glb:seat,back", "m.json": J({"seat": "../../x"})})
    add("assets-km-sized", ["assets", "add", "src", "--category", "thing"], 2, ["across"],
        files={"src/a.glb": "@glb:seat,back;2000"})
    add("assets-scale-inf", ["assets", "add", "src", "--category", "thing", "--scale", "inf"],
        2, ["--scale"], files={"src/a.glb": "@glb:seat,back"})
    add("assets-size-range-absurd", ["assets", "add", "src", "--category", "thing",
                                     "--size-range", "0,1e9"], 2, ["size range"],
        files={"src/a.glb": "@glb:seat,back"})
    lib = {"PARSE3D_CACHE": "{case}/cache"}  # the user library of the case: nothing created
    for kind, words, code in (("zero-area", ["positive area", "back"], 2),
                              ("instanced", ["at most 1,000,000 faces"], 2),
                              ("declared-huge", ["at most 1,000,000 faces"], 2),
                              ("nan", ["NaN"], 2)):
        add(f"assets-glb-{kind}", ["assets", "add", "src", "--category", "thing"], code, words,
            files={"src/a.glb": f"@bad-glb:{kind}"}, env=lib, group="assets",
            absent=["cache/library/thing"])
    add("assets-glb-flat-triangle", ["assets", "add", "src", "--category", "thing"], 0,
        ["thing"], files={"src/a.glb": "@bad-glb:flat-triangle"}, env=lib, group="assets",
        outputs=["cache"], present=["cache/library/thing/a.npz"])
    for kind, words in (("cycle", ["two joint paths"]), ("nan-origin", ["finite"]),
                        ("huge-scale", ["finite number of at most 1e6"]),
                        ("outside", ["outside the PartNet folder"]),
                        ("many-faces", ["1,000,000 faces"])):
        add(f"assets-partnet-{kind}", ["assets", "add", "src/obj", "--category", "cupboard"],
            2, words, files={"src/obj": f"@partnet:{kind}"}, env=lib, group="assets",
            absent=["cache/library/cupboard"])
    add("assets-add-missing", ["assets", "add", "nowhere", "--category", "thing"], 2,
        ["not found"])
    add("assets-show-unknown", ["assets", "show", "spaceship"], 2, ["unknown category"])
    add("assets-show-seed-negative", ["assets", "show", "desk", "--seed", "-1"], 2, ["--seed"])
    add("assets-gallery-seeds-huge", ["assets", "gallery", "--seeds", "1000"], 2, ["--seeds"])
    add("assets-render-out-is-dir", ["assets", "render", "storage_box", "-o", "o.png"], 2,
        ["o.png"], files={"o.png": "@dir"})

    # ---------------------------------------------------------------- the designer server
    add("serve-unknown-host", ["serve", "--host", "no-such-host.invalid"], 2, ["--host"])
    add("serve-workdir-missing", ["serve", "--workdir", "nowhere"], 2, ["no such folder"])

    # ---------------------------------------------------------------- exports
    for fmt, name in (("mjcf", "scene.xml"), ("obj", "scene.obj"), ("glb", "scene.glb")):
        add(f"export-foreign-{fmt}", ["export", "scene", "--format", fmt, "-o", "mine"], 2,
            [name, "not written by parse3d", "--force"],
            files={**SCENE_FILES, f"mine/{name}": "my own file", "mine/notes.txt": "mine"})
    add("export-foreign-force", ["export", "scene", "--format", "obj", "-o", "mine", "--force"],
        0, ["wrote"], files={**SCENE_FILES, "mine/scene.obj": "my own file"},
        outputs=["mine"], present=["mine/scene.obj"])

    # ---------------------------------------------------------------- layout runs (models)
    sample = ["layout", "sample", "run", "--pag", "p.json", "--out", "o"]
    add("layout-crafted-checkpoint", sample, 2, ["checkpoint.pt", "plain weights"],
        files=run_files(), absent=["pwned", "o"])
    add("layout-eval-crafted-checkpoint", ["layout", "eval", "run", "--out", "e"], 2,
        ["checkpoint.pt"], files=run_files(), absent=["pwned", "e"])
    add("layout-random-checkpoint", sample, 2, ["checkpoint.pt", "damaged"],
        files=run_files(**{"checkpoint.pt": bytes(range(256)) * 40}), absent=["o"])
    add("layout-half-config", sample, 2, ["config.json", "invalid JSON"],
        files=run_files(**{"config.json": RUN_CONFIG[:60]}), absent=["o"])
    add("layout-config-unknown-key", sample, 2, ["config.json", "surprise"],
        files=run_files(**{"config.json": RUN_CONFIG.replace('"preset"', '"surprise": 1, '
                                                                         '"preset"')}))
    add("layout-junk-npz", sample, 2, ["relation_text.npz"],
        files=run_files(**{"config.json": RUN_CONFIG.replace('"relation_encoder": "learned"',
                                                             '"relation_encoder": "text"'),
                           "relation_text.npz": b"PK\x03\x04junk"}), absent=["pwned"])
    add("layout-crafted-shape-encoder", sample, 2, ["shape_encoder.pt"],
        files=run_files(**{"config.json": RUN_CONFIG.replace(
            '{"name": "descriptor"', '{"name": "pointcloud"'), "shape_encoder.pt": CRAFTED}),
        absent=["pwned"])

    for id, text in (("layout-train-scene-list", "[1]"),
                     ("layout-train-scene-no-pag", J({"format": "parse3d-scene/2"})),
                     ("layout-train-scene-deep", "[" * 100_000 + "]" * 100_000)):
        add(id, ["layout", "train", "ds", "--out", "r"], 2, ["scene.json"],
            files={"ds/scenes/00000/scene.json": text}, absent=["r"])

    # ---------------------------------------------------------------- vlm eval
    ev = ["vlm", "eval", "--gt", "gt.jsonl", "--pred", "pred.jsonl"]
    add("vlm-eval-10mb-response", ev + ["--json"], 0, ["sgg"],
        files={"gt.jsonl": SGG_GT, "pred.jsonl": J({"id": "s1", "response": "a" * 10_000_000})})
    add("vlm-eval-10mb-box-tokens", ev + ["--json"], 0, ["sgg"],
        files={"gt.jsonl": SGG_GT, "pred.jsonl": J(
            {"id": "s1", "response": " " * 2_000_000 + "(x, " * 500_000
             + "<|box_start|>1," * 200_000})})
    add("vlm-eval-fifo-pred", ev, 2, ["not a regular file"],
        files={"gt.jsonl": SGG_GT, "pred.jsonl": "@fifo"})
    add("vlm-eval-deep-pred", ev, 2, ["nested"],
        files={"gt.jsonl": SGG_GT, "pred.jsonl": "[" * 100_000 + "]" * 100_000})
    add("vlm-eval-not-utf8", ev, 2, ["UTF-8"],
        files={"gt.jsonl": SGG_GT, "pred.jsonl": b'{"id": "s1", "response": "\xff"}'})
    add("vlm-eval-gt-wrong-shape", ev, 2, ["gt.jsonl", "line 1", "meta.objects"],
        files={"gt.jsonl": J({"id": "s1", "task": "sgg", "meta": {"objects": [1],
                                                                  "triplets": []}}),
               "pred.jsonl": J({"id": "s1", "response": ""})})
    add("vlm-eval-mcq-options-wrong", ev, 2, ["meta.options"],
        files={"gt.jsonl": J({"id": "m", "task": "relation_mcq",
                              "meta": {"answer": "A", "options": [{"kind": "relation"}]}}),
               "pred.jsonl": J({"id": "m", "response": "A"})})

    # ---------------------------------------------------------------- misc
    add("version", ["--version"], 0, ["parse3d"])
    add("valid-pag", ["validate", "p.json"], 0, ["ok"], files={"p.json": TINY})

    # ---------------------------------------------------------------- 5, 10. environments
    add("library-broken-category", ["validate", "p.json"], 0, ["skipped", "category.json"],
        files={"p.json": TINY, "cache/library/foo/category.json": "{broken",
               "cache/library/bar/category.json": J({"format": "parse3d-category/1",
                                                     "name": "bar", "parts": 3,
                                                     "size_range": ["a"], "assets": ["x.npz"]})},
        env={"PARSE3D_CACHE": "{case}/cache"}, group="env")
    add("cache-empty", ["validate", "p.json"], 2, ["PARSE3D_CACHE", "empty"],
        files={"p.json": TINY}, env={"PARSE3D_CACHE": ""}, group="env")
    add("cache-is-file", ["validate", "p.json"], 2, ["PARSE3D_CACHE", "not a folder"],
        files={"p.json": TINY, "c": "x"}, env={"PARSE3D_CACHE": "{case}/c"}, group="env")
    add("cache-under-file", ["validate", "p.json"], 2, ["PARSE3D_CACHE", "not a folder"],
        files={"p.json": TINY, "c": "x"}, env={"PARSE3D_CACHE": "{case}/c/sub"}, group="env")
    return c


CASES = _cases()
