"""The VLM spatial-reasoning benchmark (the paper's Sec. 4.1 and Table 2).

* :mod:`parse3d.vlm.build` — a built dataset -> relation MCQ, part-contact MCQ and scene-graph
  items in the ``messages`` + ``images`` JSONL layout, with a card (``vlm.json``);
* :mod:`parse3d.vlm.evaluate` — scoring predictions as in Table 2;
* :mod:`parse3d.vlm.baselines` — random, answer prior, text-only, oracle, perturbed oracle;
* :mod:`parse3d.vlm.client` — any OpenAI-compatible endpoint, or a local model;
* :mod:`parse3d.vlm.finetune` — the paper's LoRA recipe (transformers + peft).

The vocabulary shared by all tasks is in :mod:`parse3d.vlm.vocab`.
"""
