"""What the animation tests in this folder share: failing with a message,
and a fresh work folder holding a scene, its INI file and an empty
startup INI (so the user's povray.ini stays out)."""

import os
import shutil
import sys


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def make_sequence(work, name, scene_text, ini_lines):
    """Empties `work`, writes NAME.pov and NAME.ini (Input_File_Name first,
    then `ini_lines`) there. Returns (ini path, environment for frameray)."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scene = os.path.join(work, name + ".pov")
    with open(scene, "w") as f:
        f.write(scene_text)
    ini = os.path.join(work, name + ".ini")
    with open(ini, "w") as f:
        f.write("Input_File_Name=%s\n%s" % (scene, ini_lines))
    env = dict(os.environ)
    env["POVINI"] = os.path.join(work, "no-startup.ini")
    with open(env["POVINI"], "w") as f:
        f.write("; empty\n")
    return ini, env
