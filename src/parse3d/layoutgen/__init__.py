"""PAG-conditioned 3-D layout diffusion (the paper's scene-generation experiment).

A graph-transformer denoiser over object poses, conditioned (or not) on a PAG's relations,
trained on the settled scenes of a built dataset; sampling writes a normal scene folder;
evaluation measures collisions, support, relation satisfaction and physics. See
``docs/layoutgen.md``.

Modules: :mod:`.pose` (the 12-D pose and its normalisation), :mod:`.encoders` (shape and
relation embeddings), :mod:`.data` (scenes to graphs), :mod:`.model` (the network),
:mod:`.train` (training, runs), :mod:`.sample` (generation), :mod:`.evaluate` (metrics).
torch and diffusers come from the ``ml`` extra; importing this package does not import them.
"""
