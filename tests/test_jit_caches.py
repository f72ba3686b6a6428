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
