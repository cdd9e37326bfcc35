"""The GIL is released while rendering: renders in several Python threads run at once and give the
same images as one at a time; other Python code runs meanwhile."""

import threading

import numpy as np

import pathspace


def test_concurrent_renders_equal_sequential_ones():
    scene = pathspace.Scene.load("cornell-box", resolution=(32, 32))
    jobs = [("pt", "none", 1), ("pt", "hashed", 2), ("bpt", "none", 3), ("lt", "none", 4), ("pt", "consistent", 5), ("sppm", "none", 6)]
    alone = [pathspace.render(scene, i, spp=4, filter=f, seed=s, progress=False).image for i, f, s in jobs]
    together = [None] * len(jobs)
    errors = []

    def work(k):
        try:
            i, f, s = jobs[k]
            together[k] = pathspace.render(scene, i, spp=4, filter=f, seed=s, progress=False).image
        except Exception as e:  # reported below: an exception in a thread would otherwise vanish
            errors.append(e)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(len(jobs))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    for a, b in zip(alone, together):
        assert np.array_equal(a, b)


def test_python_runs_while_a_render_does():
    scene = pathspace.Scene.load("cornell-box", resolution=(96, 96))
    done = threading.Event()
    ticks = [0]

    def count():
        while not done.is_set():
            ticks[0] += 1

    counter = threading.Thread(target=count)
    counter.start()
    pathspace.render(scene, spp=32, progress=False, threads=1)
    done.set()
    counter.join()
    assert ticks[0] > 1000


def test_changing_the_camera_while_another_thread_renders_leaves_that_render_alone():
    scene = pathspace.Scene.load("cornell-box", resolution=(48, 48))
    expected = pathspace.render(scene, spp=8, seed=9, progress=False).image
    started = threading.Event()
    result = {}

    def work():
        result["image"] = pathspace.render(scene, spp=8, seed=9, progress=lambda fraction, stats: started.set()).image

    worker = threading.Thread(target=work)
    worker.start()
    assert started.wait(60)  # the render has taken its scene: the camera changes below come after
    for k in range(20):
        camera = scene.camera
        camera.fov = 30.0 + k
        scene.camera = camera
    worker.join()
    assert scene.camera.fov == 49.0
    assert np.array_equal(result["image"], expected)
    assert not np.array_equal(pathspace.render(scene, spp=8, seed=9, progress=False).image, expected)
