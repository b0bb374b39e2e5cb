#!/usr/bin/env python3
"""A throwaway PostgreSQL server for the tests, from Debian's packages (postgresql): `initdb` in
a temporary folder, the server listening on a unix socket inside that folder only (no TCP port,
so nothing on the machine is in the way), each test's database made by CREATE DATABASE, the
whole cluster stopped and removed at the end. No service, no root-owned files.

PostgreSQL refuses to run as root: run as root, the cluster's programs run as `nobody` (setpriv),
owner of the folder. Its superuser is `raygrade`, trusted on the socket.

As a module: `with Cluster() as c: url = c.new_database("t1")` (a postgresql:// URL for
`raygrade serve --database`), `c.query(url, sql)`.
As a command: `pgcluster.py COMMAND ARGS...` runs COMMAND with RAYGRADE_TEST_PG_HOST and
RAYGRADE_TEST_PG_PORT naming the server (the store tests of raygrade_tests read them), and exits
with its status; 77 (skipped) when PostgreSQL's server programs are not installed."""
import glob
import os
import pwd
import shutil
import subprocess
import sys
import tempfile
import urllib.parse

USER = "raygrade"  # the cluster's superuser
PORT = 5432  # only the socket's name: the server listens on no TCP port
SKIPPED = 77


def server_bin():
    """The folder of initdb and pg_ctl (Debian keeps them out of PATH), or None."""
    found = sorted(glob.glob("/usr/lib/postgresql/*/bin/initdb"),
                   key=lambda p: int(p.split("/")[4]) if p.split("/")[4].isdigit() else 0)
    if found:
        return os.path.dirname(found[-1])
    initdb = shutil.which("initdb")
    return os.path.dirname(initdb) if initdb else None


class Cluster:
    def __init__(self):
        self.bin = server_bin()
        if not self.bin:
            raise FileNotFoundError("PostgreSQL's server programs (initdb, pg_ctl) are not "
                                    "installed: apt-get install postgresql")
        self.tmp = tempfile.mkdtemp(prefix="raygrade-pg-")
        self.data = os.path.join(self.tmp, "data")
        self.socket = os.path.join(self.tmp, "socket")
        os.makedirs(self.socket)
        self.as_user = []
        if os.geteuid() == 0:
            nobody = pwd.getpwnam("nobody")
            for d in (self.tmp, self.socket):
                os.chown(d, nobody.pw_uid, nobody.pw_gid)
            self.as_user = ["setpriv", f"--reuid={nobody.pw_uid}", f"--regid={nobody.pw_gid}",
                            "--clear-groups"]
        self.count = 0
        self.started = False

    def run(self, *args):
        r = subprocess.run(self.as_user + list(args), cwd=self.tmp, capture_output=True,
                           text=True, timeout=120)
        if r.returncode != 0:
            raise RuntimeError(f"{' '.join(args)}: {r.stdout}{r.stderr}")
        return r.stdout

    def start(self):
        self.run(os.path.join(self.bin, "initdb"), "-D", self.data, "-A", "trust", "-U", USER,
                 "-E", "UTF8", "--locale=C", "--no-sync")
        # fsync off: the tests kill raygrade, never PostgreSQL, and a commit handed to the
        # server survives that without a disk flush.
        options = (f"-k {self.socket} -p {PORT} -c listen_addresses='' -c fsync=off "
                   "-c full_page_writes=off -c max_connections=200")
        self.run(os.path.join(self.bin, "pg_ctl"), "-D", self.data, "-l",
                 os.path.join(self.tmp, "server.log"), "-w", "-t", "60", "-o", options, "start")
        self.started = True
        return self

    def stop(self):
        if self.started:
            try:
                self.run(os.path.join(self.bin, "pg_ctl"), "-D", self.data, "-m", "immediate",
                         "-w", "stop")
            except (RuntimeError, subprocess.TimeoutExpired) as e:
                print(f"pgcluster: {e}", file=sys.stderr)
            self.started = False
        shutil.rmtree(self.tmp, ignore_errors=True)

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        self.stop()

    def url(self, name):
        host = urllib.parse.quote(self.socket, safe="")
        return f"postgresql://{USER}@/{name}?host={host}&port={PORT}"

    def new_database(self, prefix="t"):
        """A new empty database; its URL."""
        self.count += 1
        name = f"{prefix}_{self.count}"
        self.query(self.url("postgres"), f'CREATE DATABASE "{name}"')
        return self.url(name)

    def query(self, url, sql):
        """The rows of `sql` on the database at `url`, as lists of text."""
        r = subprocess.run(["psql", "-X", "-q", "-A", "-t", "-F", "\t", "-v", "ON_ERROR_STOP=1",
                            "-d", url, "-c", sql], capture_output=True, text=True, timeout=60)
        if r.returncode != 0:
            raise RuntimeError(f"psql {sql!r}: {r.stderr}")
        return [line.split("\t") for line in r.stdout.splitlines() if line]


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        cluster = Cluster()
    except FileNotFoundError as e:
        print(f"pgcluster: skipped: {e}", file=sys.stderr)
        return SKIPPED
    with cluster:
        env = dict(os.environ, RAYGRADE_TEST_PG_HOST=cluster.socket,
                   RAYGRADE_TEST_PG_PORT=str(PORT))
        return subprocess.run(sys.argv[1:], env=env).returncode


if __name__ == "__main__":
    sys.exit(main())
