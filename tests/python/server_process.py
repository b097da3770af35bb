"""Runs getme-server on a free loopback port for a test (--listen=127.0.0.1:0; the port is read
from the server's "listening on port N" log line, so there is no race for a port)."""

import re
import socket
import subprocess
import threading
import time


class ServerProcess:
    def __init__(self, binary, *flags, start_timeout=30.0):
        self.process = subprocess.Popen([binary, "--listen=127.0.0.1:0", *flags],
                                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        text=True)
        self.log = []
        port = self._wait_for_port(start_timeout)
        self.address = f"127.0.0.1:{port}"
        # Keep draining the log so the server never blocks on a full pipe.
        self._drain = threading.Thread(target=self._read_rest, daemon=True)
        self._drain.start()

    def _wait_for_port(self, timeout):
        deadline = time.monotonic() + timeout
        for line in self.process.stdout:
            self.log.append(line)
            match = re.search(r"listening on port (\d+)", line)
            if match:
                return int(match.group(1))
            if time.monotonic() > deadline:
                break
        self.process.kill()
        raise RuntimeError("getme-server did not start:\n" + "".join(self.log))

    def _read_rest(self):
        for line in self.process.stdout:
            self.log.append(line)

    def stop(self):
        """SIGTERM; returns the exit code (the server drains and exits 0)."""
        self.process.terminate()
        try:
            code = self.process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            self.process.kill()
            code = self.process.wait()
        self._drain.join(timeout=5)
        self.process.stdout.close()
        return code


def unused_address():
    """A loopback address nothing listens on (a port bound and released again)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return f"127.0.0.1:{s.getsockname()[1]}"
