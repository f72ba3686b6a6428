"""Stale numba caches are removed when any source of the package changes (particle_methods.jit)."""

from particle_methods.jit import clear_stale_caches


def make_package(root):
    (root / "sub" / "__pycache__").mkdir(parents=True)
    (root / "a.py").write_text("x = 1\n")
    (root / "sub" / "b.py").write_text("y = 2\n")
    caches = [root / "sub" / "__pycache__" / "b.f-1.py311.nbi", root / "sub" / "__pycache__" / "b.f-1.py311.1.nbc"]
    for cache in caches:
        cache.write_bytes(b"machine code")
    return caches


def test_caches_survive_while_the_sources_are_unchanged(tmp_path):
    caches = make_package(tmp_path)
    stamp = tmp_path / "stamp"
    stamp.write_text("")  # a stamp of other sources: the first call clears
    assert clear_stale_caches(tmp_path, stamp)
    for cache in caches:
        cache.write_bytes(b"recompiled")
    assert not clear_stale_caches(tmp_path, stamp)
    assert all(cache.exists() for cache in caches)


def test_an_edit_in_another_module_clears_every_cache(tmp_path):
    """A kernel of sub/b.py may call a compiled function of a.py: editing a.py must clear b's caches."""
    caches = make_package(tmp_path)
    stamp = tmp_path / "stamp"
    clear_stale_caches(tmp_path, stamp)
    for cache in caches:
        cache.write_bytes(b"compiled from the old a.py")
    (tmp_path / "a.py").write_text("x = 3\n")
    assert clear_stale_caches(tmp_path, stamp)
    assert not any(cache.exists() for cache in caches)


#: A process that compiles the kernel of ``kernel.py`` in ``sys.argv[1]``: it says it is ready (a file), starts once
#: ``go`` exists there, and prints whether it compiled (cache misses) or loaded the other's cache (hits). A
#: compilation (after a cache miss) first waits, up to ``sys.argv[2]`` seconds, until the other process misses the
#: cache too: without a lock both then compile, however late the other started (on a loaded machine it can start
#: after the first has written its cache); with the lock the other never gets there, and the wait runs out.
COMPILER = """
import os, sys, time
from pathlib import Path
folder, wait = Path(sys.argv[1]), float(sys.argv[2])
sys.path.insert(0, str(folder))
import kernel
dispatcher = kernel.twice
slow = dispatcher._compiler.compile
def compile_slowly(*arguments):
    (folder / f"compiling-{os.getpid()}").touch()
    deadline = time.monotonic() + wait
    while len(list(folder.glob("compiling-*"))) < 2 and time.monotonic() < deadline:
        time.sleep(0.005)
    return slow(*arguments)
dispatcher._compiler.compile = compile_slowly
(folder / f"ready-{os.getpid()}").touch()
while not (folder / "go").exists():
    time.sleep(0.005)
assert dispatcher(2.0) == 4.0
print(sum(dispatcher.stats.cache_misses.values()), sum(dispatcher.stats.cache_hits.values()))
"""


def test_two_processes_asking_for_a_kernel_at_once_compile_it_once(tmp_path):
    """Two processes start together on an empty cache: one compiles (made to wait 2 s for the other to miss the
    cache too), the other waits for its lock and loads its cache. Without the lock (numba's own njit) both compile,
    whatever the machine's load (each waits until the other has missed the cache)."""
    import subprocess
    import sys
    import time

    for jit, expected, wait in (("particle_methods.jit", [(1, 0), (0, 1)], 2.0), ("numba", [(1, 0), (1, 0)], 120.0)):
        folder = tmp_path / jit
        folder.mkdir()
        (folder / "kernel.py").write_text(f"from {jit} import njit\n\n@njit(cache=True)\ndef twice(x):\n"
                                          "    return 2.0 * x\n")
        processes = [subprocess.Popen([sys.executable, "-c", COMPILER, str(folder), str(wait)],
                                      stdout=subprocess.PIPE, text=True) for _ in range(2)]
        deadline = time.monotonic() + 120
        while len(list(folder.glob("ready-*"))) < 2 and time.monotonic() < deadline:
            time.sleep(0.005)
        (folder / "go").touch()
        counts = sorted((tuple(map(int, process.communicate(timeout=300)[0].split())) for process in processes),
                        reverse=True)
        assert all(process.returncode == 0 for process in processes)
        assert counts == expected, jit
