"""The drawing of a run directory by one process (plots/plot_result.py): the
libraries are imported once, then the pictures (pictures.py), the statistics
page where the run wrote statistics.csv (statistics.py) and, when asked, the
animation (movie_files.py) are drawn by as many worker processes as there
are free cores to run them, forked after the imports. The workers take the jobs from
one queue, the costliest first, so that the animation runs beside the pictures
and two pictures never wait for each other.

A job that fails does not stop the others: its traceback goes to stderr, and
the process ends with the first failure's one line (exit 1), or with "cannot
write PATH: REASON" (exit 4) when the system refused a file (a full disk).
"""
import os
import signal
import sys
import traceback

from .movie_files import draw_animation
from .pictures import called_for, draw
from .run_files import open_result, read_summary
from .saving import CannotWrite
from .statistics import CSV as STATISTICS_CSV
from .statistics import PNG as STATISTICS_PNG
from .statistics import draw_statistics

ANIMATION = "animation"
# What a job costs, roughly (the queue hands the costliest out first).
COST = {ANIMATION: 100, "fields.png": 6, "clusters.png": 5, "temperature.png": 4, "evolution.png": 4,
        "regimes.png": 3, "velocity_distribution.png": 2, "spacetime.png": 2, STATISTICS_PNG: 4}
FAILED, CANNOT_WRITE = 1, 4  # exit codes (plots/plot_result.py)
BUSY = 50  # per cent of the time some task waited for a CPU


def jobs(out_dir, animation):
    """The run's pictures, its statistics page where it wrote statistics.csv and,
    with `animation`, the animation: costliest first."""
    with open_result(out_dir) as f:
        names = list(called_for(f, read_summary(out_dir, missing={})))
    names += [ANIMATION] if animation else []
    names += [STATISTICS_PNG] if os.path.exists(os.path.join(out_dir, STATISTICS_CSV)) else []
    return sorted(names, key=lambda name: -COST.get(name, 1))


def free_cores():
    """The cores the workers may share: those this process may run on, or one
    when they are taken (tasks waited for a CPU more than BUSY % of the last
    10 s, /proc/pressure/cpu): there a second worker would only add the cost of
    its fork (its copies of the parent's pages) to the drawing's."""
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:
        cores = os.cpu_count() or 1
    try:
        with open("/proc/pressure/cpu") as f:
            some = f.readline().split()  # some avg10=0.00 avg60=0.00 avg300=0.00 total=0
        if float(some[1].split("=")[1]) > BUSY:
            return 1
    except (OSError, IndexError, ValueError):
        pass
    return cores


def _die_with(parent):
    """A worker ends when the process that forked it ends (it is killed by the
    command that stops it, which knows only its direct child)."""
    try:
        import ctypes

        ctypes.CDLL(None).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass
    if os.getppid() != parent:
        os._exit(FAILED)


def _work(out_dir, names, queue, report, who):
    """Takes job after job (one byte: its index in names) until the queue is
    empty; writes a line "CODE<tab>MESSAGE" to `report` for each failure."""
    summary = read_summary(out_dir, missing={})
    with open_result(out_dir) as f:
        while True:
            taken = os.read(queue, 1)
            if not taken:
                return
            name = names[taken[0]]
            try:
                if name == ANIMATION:
                    draw_animation(out_dir, who)
                elif name == STATISTICS_PNG:
                    draw_statistics(out_dir)
                else:
                    draw(f, summary, out_dir, name)
            except CannotWrite as exc:
                os.write(report, f"{CANNOT_WRITE}\t{exc}\n".encode())
                return  # no room: the other jobs would fail the same way
            except Exception as exc:
                traceback.print_exc()
                reason = (f"{type(exc).__name__}: {exc}".splitlines() or [""])[0]
                os.write(report, f"{FAILED}\t{name}: {reason}\n".encode())


def _worker(out_dir, names, queue, report, who, parent):
    """A forked worker: works, then ends without the parent's exit handlers."""
    code = 0
    try:
        _die_with(parent)
        _work(out_dir, names, queue, report, who)
    except BaseException as exc:  # outside a job: opening the file, an interrupt
        traceback.print_exc()
        os.write(report, f"{FAILED}\t{type(exc).__name__}: {exc}\n".encode())
        code = FAILED
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(code)


def _read_all(fd):
    chunks = []
    while True:
        chunk = os.read(fd, 65536)
        if not chunk:
            return b"".join(chunks).decode(errors="replace")
        chunks.append(chunk)


def draw_run(out_dir, animation=False, who="plot_result.py", workers=None):
    """Draws the run in out_dir; returns (exit code, the line to end with or "")."""
    names = jobs(out_dir, animation)
    workers = max(1, min(workers or free_cores(), len(names)))
    queue_out, queue_in = os.pipe()
    os.write(queue_in, bytes(range(len(names))))
    os.close(queue_in)
    report_out, report_in = os.pipe()
    children = []
    if workers == 1:
        _work(out_dir, names, queue_out, report_in, who)
    else:
        sys.stdout.flush()
        sys.stderr.flush()
        parent = os.getpid()
        for _ in range(workers):
            pid = os.fork()
            if pid == 0:
                os.close(report_out)
                _worker(out_dir, names, queue_out, report_in, who, parent)
            children.append(pid)
    os.close(report_in)
    said = _read_all(report_out)  # to its end: every worker has ended or closed it
    statuses = [os.waitpid(pid, 0)[1] for pid in children]
    os.close(report_out)
    os.close(queue_out)
    return _outcome(said, statuses)


def _outcome(said, statuses):
    failures = [line.split("\t", 1) for line in said.splitlines() if "\t" in line]
    for code, message in failures:
        if int(code) == CANNOT_WRITE:
            return CANNOT_WRITE, message
    for status in statuses:
        if os.WIFSIGNALED(status):
            return FAILED, f"a drawing process ended by signal {os.WTERMSIG(status)}"
    if failures:
        return FAILED, failures[0][1]
    return 0, ""
