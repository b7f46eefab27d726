"""A single-node Slurm cluster on this machine, for the tests: munged, slurmctld and slurmd started in the
foreground by this process from a configuration it writes into a temporary directory, and stopped by it.

    with SingleNodeCluster(work_dir) as cluster:
        subprocess.run(["sbatch", ...], env=cluster.env)

Debian's packages: slurm-wlm (slurmctld, slurmd, slurm-client) and munge (scripts/install-deps.sh --report).
Nothing outside the directory is touched: ports are free ones picked at start, state, spool, logs, the munge key
and socket live in the directory, and the client commands find the cluster through SLURM_CONF in `env`. slurmd
has to be root to start jobs as the user who submitted them (as root it runs them as root); a user who is not
root runs all three daemons as themselves (SlurmUser and SlurmdUser are that user), and jobs run as that user.
"""
from __future__ import annotations

import os
import pwd
import shutil
import signal
import socket
import subprocess
import time
from pathlib import Path

DAEMONS = {"munged": "munge", "slurmctld": "slurmctld", "slurmd": "slurmd"}
CLIENTS = {"sbatch": "slurm-client", "squeue": "slurm-client", "scontrol": "slurm-client", "sinfo": "slurm-client",
           "scancel": "slurm-client"}
NODE = "sphnode"


class ClusterError(RuntimeError):
    pass


def find(program: str, package: str) -> str:
    path = shutil.which(program) or shutil.which(program, path="/usr/sbin:/sbin")
    if path is None:
        raise ClusterError(f"{program} not found (Debian package {package}: scripts/install-deps.sh --report)")
    return path


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def slurm_conf(d: Path, host: str, user: str, cpus: int, ctl_port: int, node_port: int, munge_socket: Path) -> str:
    """slurm.conf of one node (this host) with every path under d; no cgroups, no accounting database."""
    return f"""# Written by validation/matrix/slurm_cluster.py: a single-node cluster for the tests.
ClusterName=sphtest
SlurmctldHost={host}(127.0.0.1)
SlurmctldPort={ctl_port}
SlurmdPort={node_port}
SlurmUser={user}
SlurmdUser={user}
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={munge_socket}
StateSaveLocation={d}/state
SlurmdSpoolDir={d}/spool
SlurmctldPidFile={d}/slurmctld.pid
SlurmdPidFile={d}/slurmd.pid
SlurmctldLogFile={d}/slurmctld.log
SlurmdLogFile={d}/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
SlurmdParameters=config_overrides
MinJobAge=600
KillWait=5
MailProg=/bin/true
NodeName={NODE} NodeHostname={host} NodeAddr=127.0.0.1 CPUs={cpus} State=UNKNOWN
PartitionName=local Nodes={NODE} Default=YES MaxTime=INFINITE State=UP
"""


class SingleNodeCluster:
    def __init__(self, directory: Path, cpus: int | None = None, start_limit_s: float = 60.0):
        self.dir = Path(directory).resolve()
        self.cpus = cpus or os.cpu_count() or 1
        self.start_limit_s = start_limit_s
        self.procs = []  # (name, Popen) in start order
        self.env = dict(os.environ)

    def _wait_for(self, what: str, ready, log: Path) -> None:
        deadline = time.monotonic() + self.start_limit_s
        while time.monotonic() < deadline:
            for name, p in self.procs:
                if p.poll() is not None:
                    raise ClusterError(f"{name} exited {p.returncode} while waiting for {what}: "
                                       f"{log.read_text()[-2000:] if log.exists() else ''}")
            if ready():
                return
            time.sleep(0.2)
        raise ClusterError(f"{what} not ready after {self.start_limit_s} s; {log}: "
                           f"{log.read_text()[-2000:] if log.exists() else '(no log)'}")

    def _start(self, name: str, command: list, log: Path) -> None:
        out = open(log, "ab")
        self.procs.append((name, subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT, env=self.env,
                                                  start_new_session=True)))
        out.close()

    def start(self) -> "SingleNodeCluster":
        bins = {p: find(p, pkg) for p, pkg in {**DAEMONS, **CLIENTS}.items()}
        d = self.dir
        for sub in ("state", "spool", "munge"):
            (d / sub).mkdir(parents=True, exist_ok=True)
        os.chmod(d / "munge", 0o700)
        key = d / "munge" / "munge.key"
        key.write_bytes(os.urandom(1024))
        os.chmod(key, 0o600)
        sock = d / "munge" / "munge.socket"
        self._start("munged", [bins["munged"], "--foreground", "--force", "--key-file", str(key), "--socket",
                               str(sock), "--pid-file", str(d / "munge" / "munged.pid"), "--log-file",
                               str(d / "munge" / "munged.log"), "--seed-file", str(d / "munge" / "munged.seed")],
                    d / "munged.out")
        self._wait_for("munged's socket", sock.exists, d / "munge" / "munged.log")
        user = pwd.getpwuid(os.getuid()).pw_name
        conf = d / "slurm.conf"
        conf.write_text(slurm_conf(d, socket.gethostname().split(".")[0], user, self.cpus, free_port(), free_port(),
                                   sock))
        self.env["SLURM_CONF"] = str(conf)
        self._start("slurmctld", [bins["slurmctld"], "-D", "-f", str(conf)], d / "slurmctld.out")
        self._start("slurmd", [bins["slurmd"], "-D", "-f", str(conf), "-N", NODE], d / "slurmd.out")

        def node_idle() -> bool:
            done = subprocess.run([bins["sinfo"], "-h", "-n", NODE, "-o", "%T"], capture_output=True, text=True,
                                  env=self.env)
            return done.returncode == 0 and done.stdout.strip() == "idle"
        self._wait_for(f"node {NODE} idle in sinfo", node_idle, d / "slurmd.log")
        return self

    def stop(self) -> None:
        """Cancels what is still queued, then ends the daemons (SIGTERM, SIGKILL after 10 s), last started first."""
        if any(name == "slurmctld" and p.poll() is None for name, p in self.procs):
            subprocess.run(["scancel", "--full", "--partition", "local"], env=self.env, capture_output=True)
        for name, p in reversed(self.procs):
            if p.poll() is None:
                p.send_signal(signal.SIGTERM)
                try:
                    p.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    p.kill()
                    p.wait()
        self.procs = []

    def __enter__(self):
        try:
            return self.start()
        except BaseException:
            self.stop()
            raise

    def __exit__(self, *exc):
        self.stop()
        return False
