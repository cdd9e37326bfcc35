"""No memory growth over 200 renders. The measure is the C heap in use (glibc's mallinfo2: bytes in
allocated chunks, mmap'd ones included), which a leak raises by exactly what it loses. The resident
set is only a coarse second check: it also moves with the allocators' caches and fragmentation (the
thread pool's per-thread arenas), and grew 7.5% over these renders on a loaded CI machine with
nothing leaked, which the earlier 5% bound on it took for a leak."""

import ctypes
import gc

import pathspace


class _Mallinfo2(ctypes.Structure):
    _fields_ = [(name, ctypes.c_size_t) for name in
                ("arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks", "uordblks", "fordblks", "keepcost")]


_libc = ctypes.CDLL("libc.so.6")
_libc.mallinfo2.restype = _Mallinfo2


def heap_in_use():
    info = _libc.mallinfo2()
    return info.uordblks + info.hblkhd


def resident_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


def test_no_memory_growth_over_200_renders():
    scene = pathspace.Scene.load("cornell-box", resolution=(64, 64))
    for _ in range(10):  # settles the thread pool and the allocators' caches
        pathspace.render(scene, spp=1, filter="hashed", progress=False)
    gc.collect()
    heap_before, resident_before, objects_before = heap_in_use(), resident_bytes(), len(gc.get_objects())
    for k in range(200):
        result = pathspace.render(scene, spp=1, filter="hashed", seed=k, progress=lambda fraction, stats: None)
        assert result.image.shape == (64, 64, 3)
    del result
    gc.collect()
    heap_growth = heap_in_use() - heap_before
    # One leaked 64x64 image a render would be 200 x 48 KiB = 9.4 MiB; a leak of 5 KiB a render fails.
    assert heap_growth < 1 << 20, "heap in use grew by {} bytes over 200 renders".format(heap_growth)
    assert len(gc.get_objects()) <= objects_before + 100, "Python objects are left over from the renders"
    resident_after = resident_bytes()
    assert resident_after <= resident_before * 1.25, "resident set grew from {} to {} bytes".format(resident_before, resident_after)
