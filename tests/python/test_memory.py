"""No memory growth over 200 renders: the resident set after them is within 5% of where it was
after the first few (which settle the allocators and the thread pool)."""

import gc

import pathspace


def resident_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


def test_no_memory_growth_over_200_renders():
    scene = pathspace.Scene.load("cornell-box", resolution=(64, 64))
    for _ in range(10):
        pathspace.render(scene, spp=1, filter="hashed", progress=False)
    gc.collect()
    before = resident_bytes()
    for k in range(200):
        result = pathspace.render(scene, spp=1, filter="hashed", seed=k, progress=lambda fraction, stats: None)
        assert result.image.shape == (64, 64, 3)
    del result
    gc.collect()
    after = resident_bytes()
    assert after <= before * 1.05, "resident set grew from {} to {} bytes".format(before, after)
