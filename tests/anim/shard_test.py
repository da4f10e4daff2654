#!/usr/bin/env python3
"""Sharding: N processes on N shards of one sequence, into one folder, give
the frames one process gives, byte for byte; a scene whose frames pass
state through files is refused.

    shard_test.py FRAMERAY REPO_ROOT WORKDIR [SHARDS]

1. The demo animation (ini/demo.ini, 160x120, 24 frames, a subset 3..22
   with Frame_Step 1) rendered by one process into one/.
2. The same options with Shard_Index=i Shard_Count=N for i in 0..N-1, all
   processes at once, into shared/: the union of their PNGs must equal
   one/'s (names and bytes); no shard may write another's frame, each
   writes its own journal and sequence.shard-I-of-N.json, and the last to
   finish merges them into sequence.json.
3. A shard killed mid-run and run again with +C finishes its frames.
4. tests/anim/state_passing/bounce.pov with +SHC2: refused (exit != 0,
   a message naming Shard_Count, no image, no state file written).
"""
import glob
import json
import os
import shutil
import signal
import subprocess
import sys

from sequence_fixture import fail
import time


def pngs(folder):
    out = {}
    for path in sorted(glob.glob(os.path.join(folder, "*.png"))):
        with open(path, "rb") as f:
            out[os.path.basename(path)] = f.read()
    return out


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    frameray, root, work = os.path.abspath(sys.argv[1]), sys.argv[2], os.path.abspath(sys.argv[3])
    shards = int(sys.argv[4]) if len(sys.argv) > 4 else 3
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    base = [frameray, "ini/demo.ini", "+W160", "+H120", "+SF3", "+EF22", "-V"]

    one = os.path.join(work, "one")
    proc = subprocess.run(base + ["+O" + one + "/"], cwd=root, capture_output=True, text=True, timeout=240)
    if proc.returncode != 0:
        fail(f"one process: exit {proc.returncode}\n{proc.stderr}")
    reference = pngs(one)
    if len(reference) != 20:
        fail(f"one process wrote {len(reference)} frames, expected 20")

    shared = os.path.join(work, "shared")
    procs = [subprocess.Popen(base + ["+O" + shared + "/", f"Shard_Index={i}", f"+SHC{shards}", "+WT1"], cwd=root,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for i in range(shards)]
    for i, p in enumerate(procs):
        _, err = p.communicate(timeout=240)
        if p.returncode != 0:
            fail(f"shard {i}: exit {p.returncode}\n{err}")
    union = pngs(shared)
    if sorted(union) != sorted(reference):
        fail(f"shards wrote {sorted(union)}, one process {sorted(reference)}")
    for name, data in reference.items():
        if union[name] != data:
            fail(f"{name} differs between the shards and one process")
    for i in range(shards):
        stats_path = os.path.join(shared, f"sequence.shard-{i}-of-{shards}.json")
        if not os.path.exists(stats_path):
            fail(f"no {stats_path}")
        with open(stats_path) as f:
            stats = json.load(f)
        numbers = [frame["number"] for frame in stats["frames"]]
        expected = list(range(3 + i, 23, shards))
        if numbers != expected:
            fail(f"shard {i} rendered frames {numbers}, expected {expected}")
        if not os.path.exists(os.path.join(shared, f".demo.shard-{i}-of-{shards}.frameray-journal")):
            fail(f"shard {i} wrote no journal of its own")
    print(f"{shards} shards: union of {len(union)} frames byte-identical to one process")
    # The last shard to finish merged the shards' statistics (issue 28).
    whole = os.path.join(shared, "sequence.json")
    if not os.path.exists(whole):
        fail("no sequence.json merged from the shards' statistics")
    with open(whole) as f:
        stats = json.load(f)
    numbers = [frame["number"] for frame in stats["frames"]]
    if numbers != list(range(3, 23)) or stats["shard_count"] != shards or len(stats["shards"]) != shards:
        fail(f"merged sequence.json: frames {numbers}, shard_count {stats['shard_count']}")
    print(f"sequence.json merged from {shards} shards: frames 3..22")

    # A shard that dies is run again with +C (what a Slurm requeue or a
    # Kubernetes retry does): it keeps its finished frames and renders the rest.
    resumed = os.path.join(work, "resumed")
    os.makedirs(resumed)
    args = base + ["+O" + resumed + "/", "+SHI0", f"+SHC{shards}", "+WT1"]
    p = subprocess.Popen(args, cwd=root, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(0.6)
    p.send_signal(signal.SIGKILL)
    p.wait()
    proc = subprocess.run(args + ["+C"], cwd=root, capture_output=True, text=True, timeout=240)
    if proc.returncode != 0:
        fail(f"resumed shard: exit {proc.returncode}\n{proc.stderr}")
    mine = pngs(resumed)
    expected = {n: d for n, d in reference.items() if (int(n[4:6]) - 3) % shards == 0}
    if mine != expected:
        fail(f"resumed shard 0 has {sorted(mine)}, expected {sorted(expected)} byte-identical")
    leftovers = [n for n in os.listdir(resumed) if n.endswith(".tmp")]
    if leftovers:
        fail(f"temporary files left: {leftovers}")
    print("a killed shard resumed with +C: its frames byte-identical")

    # Frames passing state through files cannot be split.
    state = os.path.join(work, "state")
    os.makedirs(state)
    for name in ("bounce.pov", "bounce.ini"):
        shutil.copy(os.path.join(root, "tests", "anim", "state_passing", name), state)
    before = set(os.listdir(state))
    # Shard 0 starts with the frame that writes the state, shard 1 with one
    # that reads what shard 0 would have written.
    for index in (0, 1):
        proc = subprocess.run([frameray, "bounce.ini", f"+SHI{index}", "+SHC2", "-V"], cwd=state, capture_output=True,
                              text=True, timeout=120)
        if proc.returncode == 0:
            fail(f"a state-passing scene was sharded (shard {index})")
        if "Shard_Count" not in proc.stderr or "state through files" not in proc.stderr:
            fail(f"the refusal of shard {index} does not say why:\n{proc.stderr}")
        print(f"state-passing scene refused (shard {index}):", proc.stderr.strip().splitlines()[0])
    written = set(os.listdir(state)) - before
    if any(n.endswith(".png") or n == "bounce_state.txt" for n in written):
        fail(f"a refused shard wrote files: {sorted(written)}")
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
