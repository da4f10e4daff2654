#!/usr/bin/env python3
"""A single-node Slurm cluster runs examples/slurm/render_array.sbatch.

    slurm_test.py FRAMERAY REPO_ROOT WORKDIR

0. Without slurm-wlm and munge it runs scripts/setup.sh (it never skips).
1. A minimal cluster in a temporary folder: its own munge key and munged
   socket, a generated slurm.conf (this host as the only node, a partition
   of 2 CPUs, no accounting database, no cgroups), slurmctld and slurmd.
2. The demo animation (ini/demo.ini, 24 frames at 640x480, anti-aliased) submitted with
   `sbatch` as a job array of 3 tasks - the example script unchanged, its
   parameters given as it documents them (INI, OUT, FRAMERAY in the
   environment, sbatch options on the command line override its #SBATCH
   lines, frameray options after the script).
3. Task 1 is cancelled with `scancel` in the middle of a frame (after its
   first frame is written, before its last), then put back with
   `scontrol requeue`: it runs again with +C, keeps the frames its journal
   records and renders the rest.
4. When the array has left `squeue`, every task must be COMPLETED (exit
   0:0) in `scontrol show job`, task 1 with one restart, and the union of
   the frames in the shared folder must be byte for byte what one plain
   frameray process writes.
5. The last shard to finish wrote sequence.json for the whole sequence;
   `frameray --merge-stats DIR` writes the same file again; a plain +C run
   over the shared folder keeps all 24 frames and renders none.
6. The daemons are shut down whatever happens (finally, SIGTERM/SIGINT).

Why `scontrol show job` and not `sacct`: sacct reads the accounting
database (slurmdbd + MySQL), which a one-node test cluster does not have
(AccountingStorageType=accounting_storage/none: "Slurm accounting storage
is disabled"); `sacct --completion` reads jobcomp/filetxt but Slurm 22.05's
reader does not know array tasks ("Unknown type ArrayJobId") and shows the
array's id for every task. slurmctld keeps finished jobs for MinJobAge
seconds, so `scontrol show job` has each task's final state and exit code.
"""
import glob
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

DAEMONS = ("munged", "slurmctld", "slurmd")
CLIENTS = ("sbatch", "squeue", "scancel", "scontrol", "sinfo", "munge")
SHARDS = 3
FRAMES = 24
SIZE = ["+W640", "+H480", "+A0.01", "+R3"]  # about 0.3 CPU s a frame: a cancel lands mid-frame


def fail(message):
    print("FAIL: " + message, flush=True)
    sys.exit(1)


def log(message):
    print(f"[{time.strftime('%H:%M:%S')}] {message}", flush=True)


def pngs(folder):
    out = {}
    for path in sorted(glob.glob(os.path.join(folder, "*.png"))):
        with open(path, "rb") as f:
            out[os.path.basename(path)] = f.read()
    return out


def free_ports(n):
    socks = []
    for _ in range(n):
        s = socket.socket()
        s.bind(("127.0.0.1", 0))
        socks.append(s)
    ports = [s.getsockname()[1] for s in socks]
    for s in socks:
        s.close()
    return ports


def find(program):
    for folder in ("/usr/sbin", "/usr/bin", "/sbin", "/bin"):
        path = os.path.join(folder, program)
        if os.access(path, os.X_OK):
            return path
    return shutil.which(program)


class Cluster:
    """munged, slurmctld and slurmd on this machine, configured in `home`."""

    def __init__(self, home):
        self.home = home
        self.conf = os.path.join(home, "slurm.conf")
        self.env = dict(os.environ, SLURM_CONF=self.conf)
        self.node = socket.gethostname().split(".")[0] or "localhost"
        self.started = []

    def write_config(self):
        h = self.home
        for d in ("state", "spool", "log"):
            os.makedirs(os.path.join(h, d), exist_ok=True)
        ctld_port, slurmd_port = free_ports(2)
        # No cgroups (containers often have none writable), no accounting
        # database; jobs keep their record in slurmctld for MinJobAge s.
        lines = [
            "ClusterName=frameray-test",
            f"SlurmctldHost={self.node}(127.0.0.1)",
            f"SlurmctldPort={ctld_port}",
            f"SlurmdPort={slurmd_port}",
            "SlurmUser=root",
            "SlurmdUser=root",
            "AuthType=auth/munge",
            "CredType=cred/munge",
            f"AuthInfo=socket={h}/munge.sock",
            f"StateSaveLocation={h}/state",
            f"SlurmdSpoolDir={h}/spool",
            f"SlurmctldPidFile={h}/slurmctld.pid",
            f"SlurmdPidFile={h}/slurmd.pid",
            f"SlurmctldLogFile={h}/log/slurmctld.log",
            f"SlurmdLogFile={h}/log/slurmd.log",
            "ProctrackType=proctrack/linuxproc",
            "TaskPlugin=task/none",
            "JobAcctGatherType=jobacct_gather/none",
            "AccountingStorageType=accounting_storage/none",
            "JobCompType=jobcomp/filetxt",
            f"JobCompLoc={h}/jobcomp.txt",
            "SchedulerType=sched/backfill",
            "SchedulerParameters=sched_interval=1",
            "SelectType=select/cons_tres",
            "SelectTypeParameters=CR_Core",
            "SlurmdParameters=config_overrides",
            "MpiDefault=none",
            "ReturnToService=2",
            "JobRequeue=1",
            "MinJobAge=600",
            "KillWait=10",
            f"NodeName={self.node} NodeAddr=127.0.0.1 CPUs=2 RealMemory=2000 State=UNKNOWN",
            f"PartitionName=frames Nodes={self.node} Default=YES MaxTime=INFINITE State=UP",
        ]
        with open(self.conf, "w") as f:
            f.write("\n".join(lines) + "\n")
        with open(os.path.join(h, "munge.key"), "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(os.path.join(h, "munge.key"), 0o400)

    def run(self, *args, check=True, timeout=30):
        proc = subprocess.run(list(args), env=self.env, capture_output=True, text=True, timeout=timeout)
        if check and proc.returncode != 0:
            fail(f"{' '.join(args)}: exit {proc.returncode}\n{proc.stdout}{proc.stderr}")
        return proc

    def start(self):
        h = self.home
        self.run(find("munged"), "--force", f"--key-file={h}/munge.key", f"--socket={h}/munge.sock",
                 f"--pid-file={h}/munged.pid", f"--log-file={h}/log/munged.log", f"--seed-file={h}/munged.seed")
        self.started.append("munged")
        self.run(find("slurmctld"), "-c", "-f", self.conf)
        self.started.append("slurmctld")
        self.run(find("slurmd"), "-f", self.conf, "-N", self.node)
        self.started.append("slurmd")
        deadline = time.time() + 60
        while time.time() < deadline:
            state = self.run("sinfo", "-h", "-N", "-o", "%t", check=False).stdout.strip()
            if state == "idle":
                log(f"cluster up: node {self.node} idle, 2 CPUs, partition frames")
                return
            time.sleep(0.5)
        self.dump_logs()
        fail(f"the node did not become idle (sinfo says '{state}')")

    def dump_logs(self):
        for name in sorted(glob.glob(os.path.join(self.home, "log", "*.log"))):
            with open(name, errors="replace") as f:
                tail = f.read()[-3000:]
            print(f"--- {name} (end)\n{tail}", flush=True)

    def pid(self, daemon):
        try:
            with open(os.path.join(self.home, daemon + ".pid")) as f:
                return int(f.read().split()[0])
        except (OSError, ValueError, IndexError):
            return None

    def stop(self):
        """Cancels every job, stops slurmctld and slurmd, then munged."""
        if "slurmctld" in self.started:
            self.run("scancel", "--user=root", check=False)
            deadline = time.time() + 30
            while time.time() < deadline:
                if not self.run("squeue", "-h", check=False).stdout.strip():
                    break
                time.sleep(0.5)
            self.run("scontrol", "shutdown", check=False)
        for daemon in ("slurmd", "slurmctld", "munged"):
            if daemon not in self.started:
                continue
            pid = self.pid(daemon)
            if pid is None:
                continue
            # slurmctld and slurmd stop on `scontrol shutdown`; munged on TERM.
            for sig, wait in ((None if daemon != "munged" else signal.SIGTERM, 10), (signal.SIGTERM, 5),
                              (signal.SIGKILL, 2)):
                if sig is not None and alive(pid):
                    try:
                        os.kill(pid, sig)
                    except ProcessLookupError:
                        pass
                deadline = time.time() + wait
                while time.time() < deadline and alive(pid):
                    time.sleep(0.2)
                if not alive(pid):
                    break
        self.started = []
        log("cluster stopped")


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    # A zombie is not running; /proc says so.
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(")")[-1].split()[0] != "Z"
    except OSError:
        return False


def task_states(cluster, job):
    """{task id: (state, exit code, restarts)} from `scontrol show job`."""
    out = cluster.run("scontrol", "-o", "show", "job", job, check=False).stdout
    states = {}
    for line in out.splitlines():
        fields = dict(re.findall(r"(\w+)=(\S*)", line))
        if "ArrayTaskId" in fields and fields["ArrayTaskId"].isdigit():
            states[int(fields["ArrayTaskId"])] = (fields.get("JobState"), fields.get("ExitCode"),
                                                  int(fields.get("Restarts", "0")))
    return states


def written_frames(run_log):
    """The frame numbers a shard's run log says were written, in order."""
    try:
        with open(run_log) as f:
            return [int(m.group(1)) for m in re.finditer(r" written frame=(\d+)", f.read())]
    except OSError:
        return []


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    frameray, root, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
    if os.geteuid() != 0:
        fail("needs root: slurmd runs the tasks as their user and munged as the cluster's")
    missing = [p for p in DAEMONS + CLIENTS if not find(p)]
    if missing:
        # A fresh machine: install them as CI does, never skip.
        log(f"not installed: {', '.join(missing)}; running scripts/setup.sh")
        proc = subprocess.run(["bash", os.path.join(root, "scripts", "setup.sh")], capture_output=True, text=True,
                              timeout=200, stdin=subprocess.DEVNULL)
        print(proc.stdout[-2000:], proc.stderr[-2000:], flush=True)
        missing = [p for p in DAEMONS + CLIENTS if not find(p)]
        if proc.returncode != 0 or missing:
            fail(f"scripts/setup.sh (exit {proc.returncode}) left {', '.join(missing) or 'nothing'} missing")
    t0 = time.time()
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    env = dict(os.environ)
    env["POVINI"] = os.path.join(work, "no-startup.ini")
    with open(env["POVINI"], "w") as f:
        f.write("; empty\n")

    # The reference: one plain process.
    one = os.path.join(work, "one")
    proc = subprocess.run([frameray, "ini/demo.ini"] + SIZE + ["+O" + one + "/", "-V"], cwd=root, env=env,
                          capture_output=True, text=True, timeout=240)
    if proc.returncode != 0:
        fail(f"one process: exit {proc.returncode}\n{proc.stderr}")
    reference = pngs(one)
    if len(reference) != FRAMES:
        fail(f"one process wrote {len(reference)} frames, expected {FRAMES}")
    log(f"one process: {FRAMES} frames in {time.time() - t0:.1f} s")

    # The daemons' folder: short (the munge socket's path is limited to
    # 108 bytes) and private (munged refuses a key others can read).
    home = tempfile.mkdtemp(prefix="frameray-slurm-")
    cluster = Cluster(home)

    def stop_on_signal(signum, _frame):
        cluster.stop()
        sys.exit(128 + signum)

    signal.signal(signal.SIGTERM, stop_on_signal)
    signal.signal(signal.SIGINT, stop_on_signal)
    try:
        cluster.write_config()
        cluster.start()
        return run_array(cluster, frameray, root, work, env, reference)
    except SystemExit:
        cluster.dump_logs()
        raise
    finally:
        cluster.stop()
        shutil.rmtree(home, ignore_errors=True)
        log(f"total {time.time() - t0:.1f} s")


def run_array(cluster, frameray, root, work, env, reference):
    shared = os.path.join(work, "shared")
    logs = os.path.join(work, "logs")
    os.makedirs(shared)
    os.makedirs(logs)
    script = os.path.join(root, "examples", "slurm", "render_array.sbatch")
    # The example asks for 4 CPUs and 4G per task; this node has 2 CPUs:
    # sbatch's options override the script's #SBATCH lines.
    submit_env = dict(env, SLURM_CONF=cluster.conf, FRAMERAY=frameray, INI="ini/demo.ini", OUT=shared + "/")
    args = ["sbatch", f"--array=0-{SHARDS - 1}", "--cpus-per-task=1", "--mem=200M", "--time=00:10:00",
            f"--chdir={root}", f"--output={logs}/frameray-%A_%a.log", script] + SIZE + ["Log_Level=debug"]
    log("$ " + " ".join(args))
    t_submit = time.time()
    proc = subprocess.run(args, env=submit_env, capture_output=True, text=True, timeout=30)
    print(proc.stdout.strip(), flush=True)
    if proc.returncode != 0:
        fail(f"sbatch: exit {proc.returncode}\n{proc.stderr}")
    m = re.match(r"Submitted batch job (\d+)", proc.stdout)
    if not m:
        fail(f"sbatch said '{proc.stdout.strip()}'")
    job = m.group(1)

    # Task 1: cancelled in the middle of a frame, then requeued.
    victim = 1
    task = f"{job}_{victim}"
    run_log = os.path.join(shared, f"demo.shard-{victim}-of-{SHARDS}.frameray.log")
    shard_frames = len(range(victim, FRAMES, SHARDS))
    deadline = time.time() + 120
    while not written_frames(run_log):
        if time.time() > deadline:
            fail(f"task {task} wrote no frame in 120 s: {task_states(cluster, job)}")
        time.sleep(0.05)
    cluster.run("scancel", task)
    before = written_frames(run_log)
    log(f"$ scancel {task}   (its frames written so far: {before})")
    if len(before) >= shard_frames:
        fail(f"task {task} had finished its {shard_frames} frames before scancel; nothing was cut")
    deadline = time.time() + 60
    while True:
        state = task_states(cluster, job).get(victim, (None,))[0]
        if state == "CANCELLED":
            break
        if time.time() > deadline:
            fail(f"task {task} is {state} 60 s after scancel")
        time.sleep(0.2)
    # Slurm holds a requeued job for about 2 minutes (its begin time); a
    # user in a hurry, like this test, releases it with StartTime=now.
    cluster.run("scontrol", "requeue", task)
    cluster.run("scontrol", "update", f"JobId={task}", "StartTime=now")
    log(f"$ scontrol requeue {task}; scontrol update JobId={task} StartTime=now")

    deadline = time.time() + 240
    while cluster.run("squeue", "-h", "-j", job, check=False).stdout.strip():
        if time.time() > deadline:
            print(cluster.run("squeue", "-j", job, check=False).stdout)
            fail("the array did not finish in 240 s")
        time.sleep(0.5)
    t_done = time.time()
    states = task_states(cluster, job)
    log(f"array {job} finished {t_done - t_submit:.1f} s after sbatch: {states}")
    for i in range(SHARDS):
        state, code, restarts = states.get(i, (None, None, 0))
        if state != "COMPLETED" or code != "0:0":
            with open(os.path.join(logs, f"frameray-{job}_{i}.log"), errors="replace") as f:
                print(f.read()[-3000:])
            fail(f"task {job}_{i}: {state}, exit {code}")
        if restarts != (1 if i == victim else 0):
            fail(f"task {job}_{i} restarted {restarts} times")
    with open(os.path.join(logs, f"frameray-{task}.log"), errors="replace") as f:
        task_log = f.read()
    if "CANCELLED" not in task_log:
        fail(f"task {task}'s log (--open-mode=append) does not show the cancelled attempt:\n{task_log}")

    # What the requeued attempt kept and rendered.
    with open(run_log) as f:
        attempts = f.read().split(" run_start ")
    if len(attempts) != 3:  # text before the first run_start, then one per attempt
        fail(f"task {task}'s run log shows {len(attempts) - 1} runs, expected 2")
    kept = [int(n) for n in re.findall(r" kept frame=(\d+)", attempts[2])]
    again = [int(n) for n in re.findall(r" written frame=(\d+)", attempts[2])]
    log(f"requeued {task}: kept {kept} (+C), rendered {again}")
    if sorted(kept + again) != list(range(victim + 1, FRAMES + 1, SHARDS)):
        fail(f"requeued {task} kept {kept} and rendered {again}")
    first = [int(n) for n in re.findall(r" written frame=(\d+)", attempts[1])]
    # Log_Level=debug: the cancelled attempt had parsed a frame it never wrote.
    cut = sorted(set(int(n) for n in re.findall(r" parse_done frame=(\d+)", attempts[1])) - set(first))
    if not cut or " outcome=\"interrupted\"" not in attempts[1]:
        fail(f"task {task}'s cancelled attempt was not cut in a frame (parsed and not written: {cut})")
    log(f"scancel cut {task} in frame(s) {cut} (parsed, not written); SIGTERM ended it as 'interrupted'")
    if not before or sorted(kept) != sorted(first) or not again:
        fail(f"requeued {task} kept {kept}, rendered {again}; its cancelled attempt wrote {first}")

    union = pngs(shared)
    if sorted(union) != sorted(reference):
        fail(f"the array wrote {sorted(union)}, one process {sorted(reference)}")
    for name, data in reference.items():
        if union[name] != data:
            fail(f"{name} differs between the array and one process")
    leftovers = [n for n in os.listdir(shared) if n.endswith(".tmp")]
    if leftovers:
        fail(f"temporary files left: {leftovers}")
    log(f"union of {len(union)} frames from {SHARDS} tasks byte-identical to one process")

    check_sequence_stats(frameray, root, shared, env)
    return 0


def check_sequence_stats(frameray, root, shared, env):
    whole = os.path.join(shared, "sequence.json")
    if not os.path.exists(whole):
        fail("the last shard to finish wrote no sequence.json")
    with open(whole) as f:
        auto = f.read()
    stats = json.loads(auto)
    numbers = sorted([f["number"] for f in stats["frames"]] + [k["number"] for k in stats["kept_frames"]])
    if numbers != list(range(1, FRAMES + 1)) or stats["frames_finished"] != FRAMES:
        fail(f"sequence.json covers frames {numbers}, finished {stats['frames_finished']}")
    if stats["shard_count"] != SHARDS or len(stats["shards"]) != SHARDS:
        fail(f"sequence.json: shard_count {stats['shard_count']}, {len(stats['shards'])} shards")
    os.remove(whole)
    proc = subprocess.run([frameray, "--merge-stats", shared], env=env, capture_output=True, text=True, timeout=60)
    if proc.returncode != 0:
        fail(f"--merge-stats: exit {proc.returncode}\n{proc.stderr}")
    with open(whole) as f:
        if f.read() != auto:
            fail("--merge-stats wrote another sequence.json than the last shard")
    log(f"sequence.json: {len(stats['frames'])} frames rendered, {len(stats['kept_frames'])} kept, "
        f"{stats['cpu_seconds']:.1f} CPU s; --merge-stats gives the same file")

    # A plain +C run over the shards' folder: every frame is finished.
    before = {n: os.stat(os.path.join(shared, n)).st_mtime_ns for n in pngs(shared)}
    proc = subprocess.run([frameray, "ini/demo.ini"] + SIZE + ["+O" + shared + "/", "+C", "-V"], cwd=root, env=env,
                          capture_output=True, text=True, timeout=240)
    if proc.returncode != 0:
        fail(f"plain +C: exit {proc.returncode}\n{proc.stderr}")
    with open(os.path.join(shared, "demo.frameray.log")) as f:
        text = f.read()
    kept = re.findall(r" kept frame=(\d+)", text)
    written = re.findall(r" written frame=(\d+)", text)
    after = {n: os.stat(os.path.join(shared, n)).st_mtime_ns for n in pngs(shared)}
    if len(kept) != FRAMES or written or after != before:
        fail(f"plain +C after the array kept {len(kept)} frames and rendered {written}")
    log(f"plain +C after the array: {len(kept)} frames kept, none rendered")
    print("PASS", flush=True)


if __name__ == "__main__":
    sys.exit(main())
