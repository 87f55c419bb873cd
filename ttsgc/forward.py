"""The client half of `ttsgc serve`: hand this command to a warm server when one is up, else say so.

A command's own work takes tens of milliseconds; starting Python with the simulator, the parsers and the
models loaded takes half a second. A server (ttsgc/server.py) keeps them loaded. This module is what every
`ttsgc` process runs first, so it imports the standard library only: when no server answers it has cost a
millisecond or two, and the command runs here as it always did.

When a server answers, it is given this process's argv, working folder, environment, umask and its standard
input, output and error themselves (the file descriptors, passed over the socket), so the command's child in
the server reads and writes exactly where this process would have; the child's exit status becomes this
process's. Ctrl-C and SIGTERM here are passed on to the child; if this process dies, the child is ended.

The socket is named after everything that makes a server's answer this installation's answer: the package
version, the size and time of every source and data file of the package, and the interpreter. A server of an
older checkout, another venv or another version is therefore never reached; the server checks the same key
again on every request.
"""

from __future__ import annotations

import _signal  # signal and socket without their Python wrappers: those import enum, selectors and more
import _socket
import marshal
import os
import sys
import zlib

# Commands that gain from a warm process: every one but serve (the server itself). batch and eval
# fork their workers from the served child, warm at once; on Ray (--ray) the cluster's workers do the work, so
# those runs stay here.
FORWARDED = frozenset({"check", "fmt", "lower", "compile", "validate", "lint", "render", "maps", "import-ttsg",
                       "batch", "eval"})
NO_SERVER_ENV = "TTSGC_NO_SERVER"  # set (to anything but "" or 0): never forward, always run in this process
PROTOCOL = 1
MAX_MESSAGE = 1 << 24
_PACKAGE = os.path.dirname(os.path.abspath(__file__))
_DATA_DIRS = ("grammar", "templates")  # read by the warm server's parsers; beside or inside the package
_PASSED_ON = (_signal.SIGINT, _signal.SIGTERM)


def forward(argv: list[str]) -> int | None:
    """The exit status of the command as a server ran it, or None when no usable server answered (then
    nothing has run, and the caller runs the command itself)."""
    if os.environ.get(NO_SERVER_ENV, "0") not in ("", "0") or _command(argv) not in FORWARDED \
            or any(word == "--ray" or word.startswith("--ray=") for word in argv):
        return None
    if not hasattr(_socket, "AF_UNIX") or not all(_is_open(fd) for fd in (0, 1, 2)):
        return None
    key = server_key()
    try:
        sock = connect(socket_path(key))
    except OSError:
        return None
    try:
        request = _request(argv, key)
        return None if request is None else _run_remotely(sock, request)
    finally:
        sock.close()


def _command(argv: list[str]) -> str | None:
    """The subcommand: the first word that is not an option (the only global option, --debug, takes no value)."""
    return next((word for word in argv if not word.startswith("-")), None)


def _is_open(fd: int) -> bool:
    try:
        os.fstat(fd)
        return True
    except OSError:  # closed (2>&-): the command runs here and meets that itself
        return False


def _stream(stream) -> list | None:
    """How Python set up one of this process's standard streams, so the child writes the same bytes."""
    if stream is None:
        return None
    return [getattr(stream, "encoding", None) or "utf-8", getattr(stream, "errors", None) or "strict",
            bool(getattr(stream, "line_buffering", False)), bool(getattr(stream, "write_through", False))]


def _request(argv: list[str], key: str) -> dict | None:
    try:
        cwd = os.getcwd()
    except OSError:  # the working folder was removed: let the command meet that itself
        return None
    mask = os.umask(0o022)
    os.umask(mask)
    return {"op": "run", "protocol": PROTOCOL, "key": key, "python": python_identity(),
            "argv": [str(a) for a in argv], "argv0": sys.argv[0] if sys.argv else "ttsgc", "cwd": cwd,
            "env": dict(os.environ), "umask": mask,
            "streams": [_stream(sys.stdin), _stream(sys.stdout), _stream(sys.stderr)]}


def _run_remotely(sock, request: dict) -> int | None:
    try:
        send_message(sock, request, fds=[0, 1, 2])
    except (OSError, ValueError):
        return None
    reader = LineReader(sock)
    previous = {}

    def pass_on(signum, frame):  # to the child, which answers as this process would have
        try:
            sock.sendall(f"signal {signum}\n".encode())
        except OSError:
            pass

    try:
        for signum in _PASSED_ON:
            previous[signum] = _signal.signal(signum, pass_on)
    except ValueError:  # not the main thread: signals stay as they are
        pass
    try:
        if reader.line() != "started":  # refused (another installation) or gone: nothing ran
            return None
        last = reader.line()
        if last is not None and last.startswith("exit "):
            return int(last.split()[1])
        print("ttsgc: internal error: the ttsgc server's worker ended without an exit status (TTSGC_NO_SERVER=1 "
              "runs commands without the server)", file=sys.stderr)
        return 1
    except (OSError, ValueError):
        return 1 if reader.seen else None
    finally:
        for signum, handler in previous.items():
            _signal.signal(signum, handler)


# -- what server and client share ---------------------------------------------------------------------------

def server_dir() -> str:
    """Where the sockets live: 'server' in ttsgc's cache folder ($TTSGC_CACHE_DIR, else the user cache folder,
    found here as platformdirs finds it, without importing it). One cache, one set of servers."""
    base = os.environ.get("TTSGC_CACHE_DIR")
    if not base:
        home = os.path.expanduser("~")
        if sys.platform == "darwin":
            base = os.path.join(home, "Library", "Caches", "ttsgc")
        else:
            base = os.path.join(os.environ.get("XDG_CACHE_HOME", "").strip() or os.path.join(home, ".cache"), "ttsgc")
    return os.path.join(base, "server")


def python_identity() -> str:
    """The interpreter and the process-wide settings a forked child keeps from the server."""
    try:
        import _locale

        codeset = _locale.nl_langinfo(_locale.CODESET)
    except (ImportError, AttributeError):
        codeset = ""
    return f"{sys.executable}|{sys.version}|{sys.getfilesystemencoding()}|{sys.flags.utf8_mode}|{codeset}"


def server_key() -> str:
    """The version and a fingerprint of the installation: every file of the package and its data folders
    (path, size, modification time), where it is, and the interpreter. Stat calls only: about a millisecond."""
    from ttsgc import __version__

    entries = [_PACKAGE, python_identity()]
    roots = [_PACKAGE] + [d for name in _DATA_DIRS for d in (os.path.join(os.path.dirname(_PACKAGE), name),)
                          if os.path.isdir(d)]
    for root in roots:
        for folder, dirs, files in os.walk(root):
            dirs[:] = sorted(d for d in dirs if d != "__pycache__")
            for name in sorted(files):
                if name.endswith((".pyc", ".pyo")):
                    continue
                path = os.path.join(folder, name)
                try:
                    st = os.stat(path)
                except OSError:
                    continue
                entries.append(f"{path}|{st.st_size}|{st.st_mtime_ns}")
    text = "\n".join(entries).encode("utf-8", "surrogateescape")
    return f"{__version__}-{zlib.crc32(text):08x}{zlib.adler32(text):08x}"


def socket_path(key: str | None = None) -> str:
    return os.path.join(server_dir(), f"ttsgc-{key or server_key()}.sock")


def connect(path: str, timeout: float | None = None):
    """A connected socket (the C-level one: this module does not import `socket`)."""
    sock = _socket.socket(_socket.AF_UNIX, _socket.SOCK_STREAM)
    try:
        sock.settimeout(timeout)
        with short_address(path) as address:
            sock.connect(address)
    except BaseException:
        sock.close()
        raise
    return sock


class short_address:
    """A socket address short enough for AF_UNIX (about 107 bytes): the path itself, or on Linux the same
    file reached through an open handle of its folder (/proc/self/fd/N/name) when the cache path is long."""

    LIMIT = 100

    def __init__(self, path: str):
        self.path, self.fd = str(path), None

    def __enter__(self) -> str:
        if len(os.fsencode(self.path)) <= self.LIMIT or not os.path.isdir("/proc/self/fd"):
            return self.path
        self.fd = os.open(os.path.dirname(self.path), os.O_RDONLY | os.O_DIRECTORY)
        return f"/proc/self/fd/{self.fd}/{os.path.basename(self.path)}"

    def __exit__(self, *exc) -> None:
        if self.fd is not None:
            os.close(self.fd)


def send_message(sock, message: dict, fds: list[int] = ()) -> None:
    """A length-prefixed message (marshal: plain data only, read by the same interpreter); the file descriptors
    ride on its first bytes (SCM_RIGHTS)."""
    payload = marshal.dumps(message)
    header = len(payload).to_bytes(4, "big")
    if fds:
        rights = b"".join(fd.to_bytes(4, sys.byteorder, signed=True) for fd in fds)
        sent = sock.sendmsg([header], [(_socket.SOL_SOCKET, _socket.SCM_RIGHTS, rights)])
        if sent != len(header):
            sock.sendall(header[sent:])
    else:
        sock.sendall(header)
    sock.sendall(payload)


def decode_message(header: bytes, read) -> dict:
    """The message after its 4-byte header; read(n) returns up to n more bytes (b'' at the end)."""
    length = int.from_bytes(header, "big")
    if length > MAX_MESSAGE:
        raise ValueError("the message is too large")
    chunks, left = [], length
    while left:
        chunk = read(min(left, 1 << 16))
        if not chunk:
            raise ValueError("the message ended early")
        chunks.append(chunk)
        left -= len(chunk)
    message = marshal.loads(b"".join(chunks))
    if not isinstance(message, dict):
        raise ValueError("the message is not a dict")
    return message


class LineReader:
    """Lines of text from a socket, one at a time."""

    def __init__(self, sock):
        self.sock, self.buffer, self.seen = sock, b"", False

    def line(self) -> str | None:
        while b"\n" not in self.buffer:
            chunk = self.sock.recv(4096)
            if not chunk:
                return None
            self.buffer += chunk
        line, self.buffer = self.buffer.split(b"\n", 1)
        self.seen = True
        return line.decode("utf-8", "replace")
