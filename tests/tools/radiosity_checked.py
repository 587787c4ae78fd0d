#!/usr/bin/env python3
"""Runs radiosity as the tests do, and checks the report.json a solve wrote against
docs/reference/report.schema.json (validate_report.py).

  radiosity_checked.py RADIOSITY ARGS...

The program gets the same arguments, standard streams, environment and working directory; the
wrapper ends with its exit status, or by the signal that ended it. Afterwards, if the command
was `solve` and DIR/report.json (--output DIR, default out) was written during this run, the
report is validated: where it does not fit, the wrapper prints why and exits 1 (or with the
program's own failure).

Signals: SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2 and SIGALRM sent to the wrapper
reach the program once. The wrapper blocks them and takes them with sigwaitinfo rather than by
a handler, because a shell script started with `&` has SIGINT and SIGQUIT ignored, and a shell
cannot trap a signal it was started ignoring, while a blocked signal stays pending. The program
starts with the dispositions and signal mask the wrapper was given (ignored stays ignored), as
when it is run directly. A signal the kernel sent to the whole process group (a terminal's
Ctrl-C) already reached the program and is not sent again: the program ends at a second
SIGINT."""

import os
import resource
import signal
import subprocess
import sys

FORWARDED = [signal.SIGINT, signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT, signal.SIGUSR1, signal.SIGUSR2,
             signal.SIGALRM]
SI_KERNEL = 0x80  # si_code of a signal the kernel sent, e.g. a terminal's to its foreground group


def solve_report(args):
    """DIR/report.json when args are a solve's, else None."""
    command = next((i for i, a in enumerate(args) if not a.startswith("-")), None)
    if command is None or args[command] != "solve":
        return None
    output = "out"
    rest = args[command + 1:]
    for i, a in enumerate(rest):
        if a == "--":
            break
        if a == "--output" and i + 1 < len(rest):
            output = rest[i + 1]
        elif a.startswith("--output="):
            output = a[len("--output="):]
    return os.path.join(output, "report.json")


def identity(path):
    """What tells a rewritten file from the one before (an atomic rename makes a new inode)."""
    try:
        s = os.stat(path)
    except OSError:
        return None
    return (s.st_dev, s.st_ino, s.st_size, s.st_mtime_ns, s.st_ctime_ns)


def run(real, args):
    """Runs the program, passing signals on; its wait status."""
    inherited = {s: signal.getsignal(s) for s in FORWARDED}

    def as_inherited():
        for s in FORWARDED:
            signal.signal(s, signal.SIG_IGN if inherited[s] == signal.SIG_IGN else signal.SIG_DFL)
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)

    waited = set(FORWARDED) | {signal.SIGCHLD}
    mask = signal.pthread_sigmask(signal.SIG_BLOCK, waited)
    child = subprocess.Popen([real] + args, preexec_fn=as_inherited)
    while True:
        info = signal.sigwaitinfo(waited)
        if info.si_signo == signal.SIGCHLD:
            pid, status = os.waitpid(child.pid, os.WNOHANG)
            if pid == child.pid:
                return status
        elif info.si_code != SI_KERNEL:
            try:
                os.kill(child.pid, info.si_signo)
            except ProcessLookupError:
                pass


def end_like(status):
    """Ends this process as the program ended: its exit status, or its signal."""
    if os.WIFSIGNALED(status):
        sig = os.WTERMSIG(status)
        resource.setrlimit(resource.RLIMIT_CORE, (0, resource.getrlimit(resource.RLIMIT_CORE)[1]))
        signal.signal(sig, signal.SIG_DFL)
        signal.pthread_sigmask(signal.SIG_UNBLOCK, [sig])
        os.kill(os.getpid(), sig)
        sys.exit(128 + sig)  # a signal that does not end a process by default
    sys.exit(os.waitstatus_to_exitcode(status))


def say(lines):
    """To stderr, and to stdout as well where that is elsewhere: tests often discard one."""
    text = "".join("radiosity_checked: %s\n" % line for line in lines)
    sys.stderr.write(text)
    sys.stderr.flush()
    try:
        out, err = os.fstat(1), os.fstat(2)
        if (out.st_dev, out.st_ino) != (err.st_dev, err.st_ino):
            sys.stdout.write(text)
            sys.stdout.flush()
    except OSError:
        pass


def main(argv):
    if len(argv) < 1:
        sys.stderr.write(__doc__)
        return 2
    real, args = argv[0], argv[1:]
    report = solve_report(args)
    before = identity(report) if report else None
    status = run(real, args)
    if report and identity(report) not in (None, before):
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import validate_report
        try:
            lines = validate_report.problems(report)
        except validate_report.Unusable as e:
            lines = [str(e)]
        if lines:
            say(["%s does not fit docs/reference/report.schema.json:" % report] + lines)
            if os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0:
                return 1
    end_like(status)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
