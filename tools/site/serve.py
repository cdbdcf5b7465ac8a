"""Serves a folder on 127.0.0.1 for `scripts/site --serve` (out/site/), many requests at
once, quietly; the address in one line, and a port it cannot have in one line (exit
status 2), never a traceback.

    serve.py FOLDER PORT [--check]

With --check it only says whether the port can be had (before a build of minutes)."""

import functools
import http.server
import sys


class Server(http.server.ThreadingHTTPServer):
    daemon_threads = True
    request_queue_size = 512  # a browser opens many connections at once; so does a test


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format, *args):  # noqa: A002 (the base class's name)
        pass


def main(folder, port, check_only):
    try:
        server = Server(("127.0.0.1", port), functools.partial(QuietHandler, directory=folder))
    except OSError as error:
        print(f"scripts/site: error: cannot serve on 127.0.0.1:{port}: {error.strerror or error} "
              f"(another program has that port? give another: scripts/site --serve 8001)", file=sys.stderr)
        return 2
    if check_only:
        server.server_close()
        return 0
    print(f"serving {folder.rstrip('/')}/ at http://127.0.0.1:{port}/ (Ctrl-C stops)", flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.server_close()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2]), sys.argv[3:] == ["--check"]))
