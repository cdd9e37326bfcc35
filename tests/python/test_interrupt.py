"""Ctrl-C (KeyboardInterrupt) stops a render within one pass and keeps what was rendered."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import pathspace


def test_ctrl_c_stops_after_the_current_pass_and_keeps_it():
    scene = pathspace.Scene.load("cornell-box", resolution=(128, 128))
    passes, passes_at_signal = [], []

    def interrupt():
        passes_at_signal.append(len(passes))
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(0.5, interrupt)
    timer.start()
    started = time.monotonic()
    with pytest.raises(pathspace.RenderInterrupted) as e:
        pathspace.render(scene, spp=100000, progress=lambda fraction, stats: passes.append(stats["spp"]))
    stopped = time.monotonic() - started
    timer.join()
    result = e.value.result
    assert isinstance(e.value, KeyboardInterrupt)
    assert 1 <= result.spp < 100000
    # The pass that was running when Ctrl-C came finishes and is kept; no other pass starts. (Its
    # progress callback may not run: Python raises KeyboardInterrupt as the callback is entered.)
    assert passes_at_signal[0] <= result.spp <= passes_at_signal[0] + 1
    assert passes == list(range(1, len(passes) + 1)) and result.spp - len(passes) in (0, 1)
    assert stopped < 30
    assert np.isfinite(result.image).all() and result.image.max() > 0


def test_the_interrupted_render_equals_a_render_of_as_many_passes():
    scene = pathspace.Scene.load("cornell-box", resolution=(64, 64))
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(pathspace.RenderInterrupted) as e:
        pathspace.render(scene, spp=100000, seed=5, progress=False)
    timer.join()
    kept = e.value.result
    again = pathspace.render(scene, spp=kept.spp, seed=5, progress=False)
    assert np.array_equal(kept.image, again.image)


def test_plain_keyboard_interrupt_handlers_still_catch_it():
    scene = pathspace.Scene.load("cornell-box", resolution=(64, 64))
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        pathspace.render(scene, spp=100000, progress=False)
        interrupted = False
    except KeyboardInterrupt:
        interrupted = True
    timer.join()
    assert interrupted
