"""Runs the Cycles peer's scenes.py inside Blender and prints the CPU time of its render call.

  blender -b --factory-startup -P bench/cycles_render_cpu.py -- --peer-scenes PEER/scenes.py SCENES.PY-OPTIONS...

The peer's script builds the scene and renders it (shared/peers/cycles/README.md); this wrapper
only adds two handlers, on render_pre and render_post, that read the process's CPU time
(time.process_time: user + system, every thread, Cycles' render threads included), and prints
`RENDER_CPU {"render_call_cpu_s": S}` at the end. The span holds Cycles' scene sync, the render
and the EXR write, not Blender's start-up or the scene's construction in Python (about 1 s of CPU,
whose noise would swamp a short render); bench/fluence_bench/peer_suite.py takes the sync and the
write out by subtracting a 1-sample render's span (docs/RESULTS.md, "How to read").
"""
import json
import runpy
import sys
import time

import bpy
from bpy.app.handlers import persistent

marks = {}


@persistent  # the peer's script resets Blender to factory settings, which drops other handlers
def before_render(*_):
    marks["pre"] = time.process_time()


@persistent
def after_render(*_):
    marks["post"] = time.process_time()


def main():
    flag = sys.argv.index("--peer-scenes")
    script = sys.argv[flag + 1]
    del sys.argv[flag:flag + 2]
    bpy.app.handlers.render_pre.append(before_render)
    bpy.app.handlers.render_post.append(after_render)
    runpy.run_path(script, run_name="__main__")
    if "pre" not in marks or "post" not in marks:
        sys.exit("cycles_render_cpu.py: the peer's script rendered nothing")
    print("RENDER_CPU " + json.dumps({"render_call_cpu_s": round(marks["post"] - marks["pre"], 4)}), flush=True)


main()
