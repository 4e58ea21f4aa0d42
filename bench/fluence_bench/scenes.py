"""The benchmark scenes and the solution methods each is rendered with.

A Method is a named fluence configuration (an integrator plus extra flags, e.g. diffusion
subsurface). A FigureScene names a USD file, the resolution, the reference method and spp, the
methods of its chart and, when the Cycles peer has the same scene, the peer's scene name.
StabilityScene is read from the `# key: value` header of a bench/stability/*.usda file.
"""
import dataclasses
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]


@dataclasses.dataclass(frozen=True)
class Method:
    name: str
    integrator: str
    extra: tuple = ()


METHODS = {m.name: m for m in (
    Method("path", "path"),
    Method("path+diffusion", "path", ("--subsurface", "diffusion")),
    Method("bdpt", "bdpt"),
    Method("sppm", "sppm"),
    Method("radiosity", "radiosity"),
    Method("direct", "direct"),
    Method("whitted", "whitted"),
    Method("naive", "naive"),
)}


def method(name):
    """The method called NAME; a bare integrator name not in METHODS is that integrator alone."""
    return METHODS.get(name) or Method(name, name)


@dataclasses.dataclass(frozen=True)
class FigureScene:
    name: str
    path: str  # relative to the repository root
    res: tuple
    reference: str  # method name
    reference_spp: int  # total over the two halves
    methods: tuple
    extra: tuple = ()  # flags every fluence render of this scene takes
    peer: str = ""  # the Cycles peer's scene name (shared/peers/cycles/scenes.py), if it has this scene
    peer_args: tuple = ()  # flags every Cycles render of this scene takes (scenes.py's options)
    note: str = ""


FIGURE_SCENES = (
    FigureScene("cornell_box", "usd_samples/cornell_box.usda", (128, 128), "path", 1024,
                ("path", "bdpt", "sppm", "radiosity", "direct"), peer="cornell",
                note="diffuse only: radiosity applies; direct misses the indirect light"),
    FigureScene("material_ball", "usd_samples/material_ball/material_ball.usda", (128, 96), "path", 512,
                ("path", "bdpt", "sppm", "whitted"), note="textured, glossy and smooth specular layers"),
    FigureScene("subdivision", "usd_samples/subdivision/creased_cubes.usda", (160, 120), "path", 1024,
                ("path", "bdpt", "sppm", "radiosity"), note="Catmull-Clark with creases, diffuse"),
    FigureScene("smoke", "bench/peer_scenes/cycles_smoke.usda", (128, 128), "path", 1024,
                ("path", "bdpt", "sppm", "direct"), peer="smoke",
                note="heterogeneous VDB medium, sun and sky; the Cycles peer's scene b"),
    FigureScene("subsurface", "usd_samples/subsurface/subsurface.usda", (160, 120), "path", 1024,
                ("path", "path+diffusion", "bdpt", "sppm"), note="random-walk against diffusion subsurface"),
    FigureScene("subsurface_peer", "bench/peer_scenes/cycles_sss.usda", (128, 128), "path", 1024,
                ("path",), extra=("--subdiv-level", "4"), peer="sss", peer_args=("--sss-mfp",),
                note="the Cycles peer's scene c (subdivision level 4, Cycles' render level; Cycles' fixed-radius "
                "walk given the mean free path Standard Surface reads, `scenes.py --sss-mfp`)"),
    FigureScene("caustic_glass", "bench/scenes/caustic_glass.usda", (128, 96), "sppm", 512,
                ("path", "bdpt", "sppm", "whitted"),
                note="glass ball and a small sphere light; sppm reference (path's is firefly-ridden)"),
)

QUICK_RES_SCALE = 2  # --quick halves the resolution


@dataclasses.dataclass(frozen=True)
class StabilityScene:
    name: str
    path: str
    reference: str
    reference_spp: int
    integrators: tuple
    expect: dict
    why: str
    summary: str


def read_stability_scene(path):
    """Parses the `# stability:`, `# reference:`, `# integrators:`, `# expect:`, `# why:` header lines."""
    fields = {}
    for line in pathlib.Path(path).read_text().splitlines()[1:]:
        m = re.match(r"#\s*(\w+):\s*(.*)", line)
        if not m:
            if line.strip() and not line.startswith("#"):
                break
            continue
        key, value = m.groups()
        fields[key] = (fields[key] + " " + value) if key in fields else value
    ref = fields.get("reference", "path 1024").split()
    expect = dict(e.split("=", 1) for e in fields.get("expect", "").split() if "=" in e)
    p = pathlib.Path(path).resolve()
    return StabilityScene(p.stem, str(p.relative_to(ROOT)), ref[0], int(ref[1]) if len(ref) > 1 else 1024,
                          tuple(fields.get("integrators", "path").split()), expect, fields.get("why", ""),
                          fields.get("stability", ""))


def stability_scenes():
    return [read_stability_scene(p) for p in sorted((ROOT / "bench" / "stability").glob("*.usda"))]
