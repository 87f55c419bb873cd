"""`ttsgc serve`: a process that keeps the simulator, the parsers, the models and the map library loaded,
and runs each forwarded command (ttsgc/forward.py) in a child forked from it.

Why a child per command: libsumo holds one simulation per process, so two commands must not share one, and a
fork starts from the warm state with nothing left over from an earlier command; it also lets commands run at
once. The child runs exactly `ttsgc.cli.main(argv)` in the client's folder, with its environment, umask and
standard streams, so what it prints and writes, and its exit status, are what the command run alone gives.

One server per user, cache folder and installation (the socket's name carries the key, see forward.py); the
socket is private to the user (a 0700 folder, a 0600 socket, and the peer's uid checked). The server ends
after an idle time, on `ttsgc serve --stop`, or when its installation changes under it.
"""

from __future__ import annotations

import fcntl
import os
import select
import signal
import socket
import sys
import threading
import time
from pathlib import Path

from ttsgc.errors import ExitCode, TtsgcError, UsageError
from ttsgc.forward import (PROTOCOL, LineReader, connect, decode_message, python_identity, send_message,
                           server_dir, server_key, short_address, socket_path)
from ttsgc.runner import FORK_SAFE_THREAD

DEFAULT_IDLE_S = 3 * 3600  # a working day's pauses, not a machine's lifetime
TICK_S = 2.0  # how often an idle server looks at the clock and at its installation
REQUEST_TIMEOUT_S = 5.0  # a connected client sends its request at once


class ServerError(TtsgcError):
    exit_code = ExitCode.INTERNAL


def warm_up() -> None:
    """What a batch's workers are given (runner.warm_pipeline), for every OpenSCENARIO version, and the
    command-line parser."""
    import ttsgc.cli
    from ttsgc.runner import warm_pipeline
    from ttsgc.xsd import VERSIONS

    ttsgc.cli.cached_parser()
    warm_pipeline(versions=tuple(f"1.{minor}" for minor in sorted(VERSIONS)))


# -- starting, stopping, asking ------------------------------------------------------------------------------

def status() -> list[tuple[Path, dict]]:
    """Every server of this cache folder that answers: its socket, and its pid, key and commands served."""
    folder = Path(server_dir())
    found = []
    for path in sorted(folder.glob("ttsgc-*.sock")) if folder.is_dir() else []:
        answer = _ask(path, {"op": "status"})
        if answer.get("pid"):
            found.append((path, answer))
    return found


def stop_all(patience_s: float = 10.0) -> int:
    """Stop every server of this cache folder, of any version, and wait until they no longer listen; the
    number stopped. Commands they are running finish."""
    stopping = [path for path, _ in status() if _ask(path, {"op": "stop"}).get("stopping")]
    deadline = time.monotonic() + patience_s
    while any(path.exists() for path in stopping) and time.monotonic() < deadline:
        time.sleep(0.05)
    return len(stopping)


def _ask(path: Path, message: dict) -> dict:
    import json

    try:
        sock = connect(str(path), timeout=REQUEST_TIMEOUT_S)
    except OSError:
        return {}
    try:
        send_message(sock, message)
        line = LineReader(sock).line()
        return json.loads(line) if line else {}
    except (OSError, ValueError):
        return {}
    finally:
        sock.close()


def start(idle_s: float = DEFAULT_IDLE_S, foreground: bool = False) -> tuple[Path, int, bool]:
    """Start this installation's server, or find it running: (socket, pid, started now). In the background
    by default: this returns once the server is warm and listening."""
    key = server_key()
    path = Path(socket_path(key))
    running = _ask(path, {"op": "status"}).get("pid")
    if running:
        return path, running, False
    folder = Path(server_dir())
    try:
        folder.mkdir(parents=True, exist_ok=True)
        os.chmod(folder, 0o700)
    except OSError as exc:
        raise UsageError(f"{folder}: cannot make the server's folder: {exc.strerror or exc} (set TTSGC_CACHE_DIR to a "
                         f"writable folder)") from None
    if foreground:
        _serve(key, path, idle_s, ready=None)
        return path, os.getpid(), True
    read_end, write_end = os.pipe()
    first = os.fork()
    if first == 0:  # detach: a new session, then a grandchild that no terminal or shell waits for
        os.close(read_end)
        try:
            os.setsid()
            if os.fork() != 0:
                os._exit(0)
            _detach_streams(folder / f"{path.stem}.log")
            sys.path[:] = [os.path.abspath(entry) for entry in sys.path]  # '' and relative entries: this folder
            os.chdir("/")  # holds no folder busy; each command runs in its client's
            _serve(key, path, idle_s, ready=write_end)
        except BaseException as exc:  # noqa: BLE001 - said to the starting process, then this process ends
            try:
                os.write(write_end, f"error {type(exc).__name__}: {exc}".encode())
            except OSError:
                pass
        finally:
            os._exit(0)
    os.close(write_end)
    os.waitpid(first, 0)
    answer = b""
    while chunk := os.read(read_end, 4096):
        answer += chunk
    os.close(read_end)
    text = answer.decode("utf-8", "replace")
    if text.startswith("ready "):
        return path, int(text.split()[1]), True
    if text.startswith("running "):
        return path, int(text.split()[1]), False
    raise ServerError(f"the server did not start: {text[6:] if text.startswith('error ') else 'no answer'}")


def _detach_streams(log: Path) -> None:
    """The server's own stdin is /dev/null, its stdout and stderr a log beside the socket."""
    null = os.open(os.devnull, os.O_RDONLY)
    out = os.open(log, os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o600)
    os.dup2(null, 0)
    os.dup2(out, 1)
    os.dup2(out, 2)
    os.close(null)
    os.close(out)


def _log(text: str) -> None:
    print(f"{time.strftime('%Y-%m-%d %H:%M:%S')} ttsgc server {os.getpid()}: {text}", file=sys.stderr, flush=True)


# -- the server ---------------------------------------------------------------------------------------------

def _serve(key: str, path: Path, idle_s: float, ready: int | None) -> None:
    lock = os.open(path.with_suffix(".lock"), os.O_WRONLY | os.O_CREAT, 0o600)
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:  # another server of this installation holds it: starting or running
        os.close(lock)
        pid = _wait_for_other(path)
        if ready is not None and pid is not None:
            os.write(ready, f"running {pid}".encode())
            os.close(ready)
            return
        raise ServerError(f"another server of this installation holds {path.with_suffix('.lock')}"
                          + ("" if pid is None else f" (pid {pid})")) from None
    listener = None
    _sweep(path)
    try:
        warm_up()
        python = python_identity()
        listener = _listen(path)
        inode = os.stat(path).st_ino
        _log(f"listening on {path}")
        if ready is not None:
            os.write(ready, f"ready {os.getpid()}".encode())
            os.close(ready)
        import gc

        gc.freeze()  # what the warm-up made stays shared with every child instead of being copied on write
        _loop(listener, key, python, idle_s, lock)
    finally:
        if listener is not None:
            listener.close()
            _unlink_if_ours(path, inode)
        os.close(lock)


def _sweep(ours: Path) -> None:
    """Remove what servers that are gone left behind (their socket, lock and log): a lock nobody holds."""
    for lock_path in ours.parent.glob("ttsgc-*.lock"):
        if lock_path.stem == ours.stem:
            continue
        try:
            fd = os.open(lock_path, os.O_WRONLY)
        except OSError:
            continue
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(fd)
            continue  # a live server's
        try:
            for suffix in (".sock", ".log", ".lock"):
                lock_path.with_suffix(suffix).unlink(missing_ok=True)
        finally:
            os.close(fd)


def _wait_for_other(path: Path, patience_s: float = 30.0) -> int | None:
    deadline = time.monotonic() + patience_s
    while time.monotonic() < deadline:
        pid = _ask(path, {"op": "status"}).get("pid")
        if pid:
            return pid
        time.sleep(0.1)
    return None


def _listen(path: Path) -> socket.socket:
    if path.exists() or path.is_symlink():
        path.unlink()  # we hold the lock: whatever is there is a dead server's
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    previous = os.umask(0o177)  # the socket is born 0600
    try:
        with short_address(path) as address:
            listener.bind(address)
    finally:
        os.umask(previous)
    listener.listen(64)
    return listener


def _unlink_if_ours(path: Path, inode: int) -> None:
    try:
        if os.stat(path).st_ino == inode:
            path.unlink()
    except OSError:
        pass


def _loop(listener: socket.socket, key: str, python: str, idle_s: float, lock: int) -> None:
    children: set[int] = set()
    served = [0]
    last_activity = time.monotonic()
    stopping = False

    def on_term(signum, frame):
        nonlocal stopping
        stopping = True

    signal.signal(signal.SIGTERM, on_term)
    signal.signal(signal.SIGINT, on_term)
    while not stopping:
        children -= _reaped(children)
        if children:
            last_activity = time.monotonic()
        elif idle_s and time.monotonic() - last_activity > idle_s:
            _log(f"idle for {idle_s:g} s; stopping")
            return
        try:
            readable, _, _ = select.select([listener], [], [], TICK_S)
        except InterruptedError:
            continue
        if not readable:
            if server_key() != key:
                _log("the installation changed; stopping")
                return
            continue
        try:
            conn, _ = listener.accept()
        except OSError:
            continue
        op = _answer(conn, key, python, children, served, not_for_children=(listener.fileno(), lock))
        if op == "run":  # asking for the status is not using the server
            last_activity = time.monotonic()
        stopping = stopping or op == "stop"
    _log("stopping")


def _reaped(children: set[int]) -> set[int]:
    done = set()
    for pid in children:
        try:
            finished, _ = os.waitpid(pid, os.WNOHANG)
        except ChildProcessError:
            finished = pid
        if finished:
            done.add(pid)
    return done


def _answer(conn: socket.socket, key: str, python: str, children: set[int], served: list[int],
            not_for_children: tuple[int, ...]) -> str | None:
    """Read one request and act on it; what it asked (run, status, stop), None if nothing was understood.
    A child closes the listening socket and the server's lock, so that neither outlives the server."""
    fds: list[int] = []
    op = None
    try:
        if not _same_user(conn):
            return None
        conn.settimeout(REQUEST_TIMEOUT_S)
        request, fds = _receive(conn)
        op = request.get("op")
        if op == "status":
            conn.sendall(f'{{"pid": {os.getpid()}, "key": "{key}", "served": {served[0]}}}\n'.encode())
        elif op == "stop":
            conn.sendall(b'{"stopping": true}\n')
        elif op != "run" or request.get("protocol") != PROTOCOL or request.get("key") != key \
                or request.get("python") != python or len(fds) != 3:
            conn.sendall(b"refused\n")  # another installation's client: it runs the command itself
        else:
            conn.settimeout(None)
            pid = os.fork()
            if pid == 0:
                try:
                    for fd in not_for_children:
                        os.close(fd)
                    _child(conn, request, fds)
                finally:
                    os._exit(1)
            children.add(pid)
            served[0] += 1
    except (OSError, ValueError, EOFError, TypeError):
        pass
    finally:
        for fd in fds:
            os.close(fd)
        conn.close()
    return op


def _receive(conn: socket.socket) -> tuple[dict, list[int]]:
    """A client's request and the file descriptors that came with it (none for status and stop)."""
    header, fds, _, _ = socket.recv_fds(conn, 4, 3)
    try:
        while len(header) < 4:
            more = conn.recv(4 - len(header))
            if not more:
                raise ValueError("the request ended early")
            header += more
        return decode_message(header, conn.recv), list(fds)
    except BaseException:
        for fd in fds:
            os.close(fd)
        raise


def _same_user(conn: socket.socket) -> bool:
    """The folder and the socket's mode keep other users out; the peer's credentials are checked too."""
    if not hasattr(socket, "SO_PEERCRED"):
        return True
    import struct

    creds = conn.getsockopt(socket.SOL_SOCKET, socket.SO_PEERCRED, struct.calcsize("3i"))
    _, uid, _ = struct.unpack("3i", creds)
    return uid == os.getuid()


# -- the child: one command, as the client would have run it -------------------------------------------------

def _child(conn: socket.socket, request: dict, fds: list[int]) -> None:
    for signum in (signal.SIGTERM, signal.SIGCHLD, signal.SIGHUP):
        signal.signal(signum, signal.SIG_DFL)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        os.chdir(request["cwd"])
    except OSError:
        conn.sendall(b"refused\n")  # the client meets the same error itself, in its own words
        return
    for target, fd in enumerate(fds):
        os.dup2(fd, target)
        os.close(fd)
    fds.clear()
    os.environ.clear()
    os.environ.update(request["env"])
    os.umask(int(request["umask"]))
    sys.argv = [request.get("argv0") or "ttsgc", *request["argv"]]
    _standard_streams(request["streams"])
    conn.sendall(b"started\n")
    finished = threading.Event()
    threading.Thread(target=_watch_client, args=(conn, finished, threading.get_ident()), daemon=True,
                     name=f"{FORK_SAFE_THREAD}-client-watcher").start()
    code = _run_main(request["argv"])
    for signum in (signal.SIGINT, signal.SIGTERM):  # the command is over: a late Ctrl-C changes nothing
        signal.signal(signum, signal.SIG_IGN)
    finished.set()
    try:
        conn.sendall(f"exit {code}\n".encode())
    except OSError:
        pass
    os._exit(0)


def _run_main(argv: list[str]) -> int:
    """cli.main, then what the interpreter does at exit: the status of SystemExit, flushed streams, atexit."""
    import atexit

    from ttsgc.cli import main

    try:
        code = main(argv)
    except SystemExit as exc:  # argparse: --help (0) and usage errors (2)
        code = _exit_status(exc.code)
    except BaseException:  # noqa: BLE001 - as the interpreter would report it
        import traceback

        traceback.print_exc()
        code = 1
    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            code = 120 if code == 0 else code  # the interpreter's status when the last flush fails
    return code


def _exit_status(code) -> int:
    if code is None:
        return 0
    if isinstance(code, int):
        return code & 0xFF
    print(code, file=sys.stderr)
    return 1


def _standard_streams(streams: list) -> None:
    """New sys.stdin/stdout/stderr on fds 0-2 (now the client's), set up as the client's own were."""
    import io

    names = ("stdin", "stdout", "stderr")
    for fd, (name, spec) in enumerate(zip(names, streams)):
        if spec is None:
            setattr(sys, name, None)
            continue
        encoding, errors, line_buffering, write_through = spec
        raw = io.FileIO(fd, "rb" if fd == 0 else "wb", closefd=False)
        buffered = io.BufferedReader(raw) if fd == 0 else io.BufferedWriter(raw)
        stream = io.TextIOWrapper(buffered, encoding=encoding, errors=errors, line_buffering=line_buffering,
                                  write_through=write_through)
        setattr(sys, name, stream)
        setattr(sys, f"__{name}__", stream)


def _watch_client(conn: socket.socket, finished: threading.Event, main_thread: int) -> None:
    """Signals the client passes on; if the client goes away, the command is ended as SIGTERM ends it. They
    are sent to the main thread, so that a read or wait it is blocked in is interrupted, as in the client."""
    reader = LineReader(conn)
    while True:
        try:
            line = reader.line()
        except OSError:
            line = None
        if finished.is_set():
            return
        if line is None:
            signal.pthread_kill(main_thread, signal.SIGTERM)
            return
        if line.startswith("signal "):
            try:
                signum = int(line.split()[1])
            except ValueError:
                continue
            if signum in (signal.SIGINT, signal.SIGTERM):
                signal.pthread_kill(main_thread, signum)


def run_command(args) -> int:
    """`ttsgc serve [--stop | --status | --foreground] [--idle SECONDS]`."""
    if args.stop:
        stopped = stop_all()
        print(f"{stopped} server(s) stopped" if stopped else "no server running")
        return ExitCode.OK
    if args.status:
        found = status()
        if not found:
            print(f"no server running (its socket would be in {server_dir()})")
        current = Path(socket_path())
        for path, answer in found:
            print(f"{path}: pid {answer['pid']}, {answer.get('served', 0)} command(s) served"
                  + (" (this installation)" if path == current else " (another installation: not used)"))
        return ExitCode.OK
    path, pid, started = start(args.idle, args.foreground)
    if not args.foreground:
        print(f"{path}: {'started' if started else 'already running'}, pid {pid}"
              + (f"; stops after {args.idle:g} s idle" if args.idle and started else ""))
    return ExitCode.OK
