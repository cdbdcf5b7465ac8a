"""scripts/site --serve's server (tools/site/serve.py) against clients that misbehave:
2 500 connections that ask and go away without reading the answer, then a request that
must be answered at once (within 10 s: the stall it catches was 32 s); a NUL byte in a
path (a 400); a connection that sends nothing (closed by the server after its idle
limit); and not a line on the server's standard error throughout (no traceback). Usage: check_serve_clients.py SOURCE_DIR"""

import os
import socket
import subprocess
import sys
import tempfile
import time

failed = False


def check(what, ok):
    global failed
    print(("ok: " if ok else "FAIL: ") + what)
    failed = failed or not ok


def free_port():
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def ask(port, path, timeout=5.0):
    """The answer's status line to GET path, or what went wrong."""
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as connection:
        connection.sendall(f"GET {path} HTTP/1.0\r\n\r\n".encode())
        return connection.recv(4096).split(b"\r\n", 1)[0].decode(errors="replace")


def main(source):
    folder = tempfile.mkdtemp()
    with open(os.path.join(folder, "index.html"), "w") as page:
        page.write("<p>" + "x" * 1_000_000 + "</p>")  # larger than a socket's buffers
    port = free_port()
    errors = tempfile.TemporaryFile()
    server = subprocess.Popen(
        [
            sys.executable,
            os.path.join(source, "tools", "site", "serve.py"),
            folder,
            str(port),
        ],
        stdout=subprocess.PIPE,
        stderr=errors,
    )
    try:
        server.stdout.readline()  # "serving ..." once it listens
        # Clients that ask for a megabyte and go away: a reset or a broken pipe each.
        for _ in range(2500):
            with socket.create_connection(("127.0.0.1", port), timeout=5) as connection:
                connection.setsockopt(
                    socket.SOL_SOCKET,
                    socket.SO_LINGER,
                    b"\x01\x00\x00\x00\x00\x00\x00\x00",
                )
                connection.sendall(b"GET /index.html HTTP/1.0\r\n\r\n")
        start = time.monotonic()
        status = ask(port, "/index.html", timeout=30)
        took = time.monotonic() - start
        # 0.01 s on a quiet machine, 1.7 s beside four CPU-bound processes; the stall this
        # catches lasted 32 s: 10 s tells them apart however busy the machine is.
        check(
            f"after 2 500 clients went away, a request is answered within 10 s ({took:.2f} s: {status})",
            status.endswith("200 OK") and took < 10.0,
        )
        status = ask(port, "/a%00b")
        check(
            f"a NUL byte in the path is a 400 ({status or 'no answer'})",
            status.split(" ")[1:2] == ["400"],
        )
        # A connection that sends nothing is closed after the idle limit (10 s; 20 s allowed).
        with socket.create_connection(("127.0.0.1", port), timeout=30) as idle:
            start = time.monotonic()
            try:
                closed = idle.recv(1) == b""
            except TimeoutError:
                closed = False
            took = time.monotonic() - start
        check(
            f"an idle connection is closed by the server ({took:.1f} s; its limit is 10 s)",
            closed and took < 20,
        )
        check("the server is still running", server.poll() is None)
    finally:
        server.terminate()
        server.wait()
    errors.seek(0)
    said = errors.read().decode(errors="replace")
    check(
        f"nothing on the server's standard error ({len(said.splitlines())} lines)",
        said == "",
    )
    if said:
        print("\n".join(said.splitlines()[:10]))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
