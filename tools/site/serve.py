"""Serves a folder on 127.0.0.1 for `scripts/site --serve` (out/site/), many requests at
once, quietly; the address in one line, and a port it cannot have in one line (exit
status 2), never a traceback: a client that goes away mid-answer is no error, an idle
connection is closed after IDLE_SECONDS, a NUL byte in a path is a 400.

    serve.py FOLDER PORT [--check]

With --check it only says whether the port can be had (before a build of minutes)."""

import functools
import http.server
import sys
import urllib.parse

IDLE_SECONDS = 10  # a connection that sends nothing for this long is closed


class Server(http.server.ThreadingHTTPServer):
    daemon_threads = True
    request_queue_size = 512  # a browser opens many connections at once; so does a test

    def handle_error(self, request, client_address):
        """A client gone (a closed tab, a broken pipe, a reset) or silent is no error;
        anything else is one line."""
        error = sys.exc_info()[1]
        if not isinstance(error, OSError):
            print(
                f"scripts/site: error: a request from {client_address[0]}: {error!r}",
                file=sys.stderr,
            )


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    timeout = IDLE_SECONDS

    def log_message(self, format, *args):  # noqa: A002 (the base class's name)
        pass

    def send_head(self):
        if "\x00" in urllib.parse.unquote(self.path):
            self.send_error(400, "a NUL byte in the path")
            return None
        return super().send_head()


def main(folder, port, check_only):
    try:
        server = Server(("127.0.0.1", port), functools.partial(QuietHandler, directory=folder))
    except OSError as error:
        print(
            f"scripts/site: error: cannot serve on 127.0.0.1:{port}: {error.strerror or error} "
            f"(another program has that port? give another: scripts/site --serve 8001)",
            file=sys.stderr,
        )
        return 2
    if check_only:
        server.server_close()
        return 0
    print(
        f"serving {folder.rstrip('/')}/ at http://127.0.0.1:{port}/ (Ctrl-C stops)",
        flush=True,
    )
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.server_close()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2]), sys.argv[3:] == ["--check"]))
