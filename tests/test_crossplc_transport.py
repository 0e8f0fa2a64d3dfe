"""Leading value transports: the in-process link and OPC UA PubSub (UADP) over loopback UDP."""
from __future__ import annotations

import faulthandler
import math
import random
import socket
import threading
import time
from collections.abc import Iterator

import pytest

from plcmotion.crossplc import LocalLink
from plcmotion.kernel.leading_value import LeadingValueSample, LeadingValueSink, LeadingValueSource

HARD_LIMIT = 30.0   # wall seconds: a hanging test dumps its stacks and ends the run


@pytest.fixture(autouse=True)
def _hard_time_limit() -> Iterator[None]:
    faulthandler.dump_traceback_later(HARD_LIMIT, exit=True)
    yield
    faulthandler.cancel_dump_traceback_later()


@pytest.fixture
def uadp():
    return pytest.importorskip("plcmotion.crossplc.uadp")


@pytest.fixture
def url() -> str:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    return f"opc.udp://127.0.0.1:{port}"


def sample(i: int, **changes: object) -> LeadingValueSample:
    fields: dict[str, object] = {"time": i * 1e-3, "position": i * 0.1 + 1 / 3, "velocity": 100.0,
                                 "acceleration": -2.5, "sequence": i}
    fields.update(changes)
    return LeadingValueSample(**fields)


def collect(source: LeadingValueSource, count: int, needed: float, limit: float = 10.0) -> list:
    got: list[LeadingValueSample] = []
    deadline = time.monotonic() + limit
    while len(got) < count and time.monotonic() < deadline:
        got += source.fetch(needed)
    return got


def uadp_threads() -> list[threading.Thread]:
    return [t for t in threading.enumerate() if t.name.startswith("uadp-")]


# ------------------------------------------------------------------------------------------ LocalLink

def test_local_link_round_trip() -> None:
    link = LocalLink()
    sink: LeadingValueSink = link
    source: LeadingValueSource = link
    assert source.fetch(0.0) == []
    sent = [sample(i) for i in range(1, 4)]
    for s in sent:
        sink.send(s)
    assert len(link) == 3
    start = time.monotonic()
    assert source.fetch(1.0) == sent            # far in the future: still no waiting
    assert source.fetch(1.0) == []
    assert time.monotonic() - start < 0.05
    sink.send(sent[0])
    assert source.fetch(0.0) == [sent[0]]


# ------------------------------------------------------------------------------------------- UADP link

def test_uadp_round_trip_is_complete_ordered_and_exact(uadp, url) -> None:
    rng = random.Random(7)
    specials = [0.0, -0.0, 1 / 3, math.pi, 5e-324, 1.7976931348623157e308, -1e-300, math.inf]
    sent = [LeadingValueSample(time=i * 1e-3 + 1e-12 * i, position=rng.uniform(-1e6, 1e6),
                               velocity=specials[i % len(specials)], acceleration=rng.gauss(0.0, 1e3),
                               valid=i % 3 != 0, tracking=i % 5 == 0, modulo_length=360.0 if i % 2 else 0.0,
                               modulo_start=rng.uniform(-1.0, 1.0), sequence=i + 1,
                               delay=(i % 4) * 0.004)
            for i in range(2000)]
    with uadp.UadpLeadingValueSubscriber(url, publisher_id=11, writer_group_id=2, dataset_writer_id=3,
                                         wait_timeout=5.0) as sub, \
            uadp.UadpLeadingValuePublisher(url, publisher_id=11, writer_group_id=2,
                                           dataset_writer_id=3) as pub:
        for s in sent:
            pub.send(s)
        got = collect(sub, len(sent), sent[-1].time)
    assert len(got) == len(sent)
    assert got == sent          # dataclass equality: every float bit-exact (-0.0 == 0.0, checked below)
    assert all(math.copysign(1, g.velocity) == math.copysign(1, s.velocity) for g, s in zip(got, sent))
    assert sub.missed == 0 and sub.dropped == 0


def test_uadp_ignores_other_writers(uadp, url) -> None:
    with uadp.UadpLeadingValueSubscriber(url, dataset_writer_id=1, wait_timeout=0.3) as sub, \
            uadp.UadpLeadingValuePublisher(url, dataset_writer_id=2) as other, \
            uadp.UadpLeadingValuePublisher(url, publisher_id=9, dataset_writer_id=1) as stranger:
        other.send(sample(1))
        stranger.send(sample(1))
        assert other.flush() and stranger.flush()
        assert sub.fetch(0.001) == []


def test_uadp_drops_duplicate_and_out_of_order_sequences(uadp, url) -> None:
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=2.0) as sub, uadp.UadpLeadingValuePublisher(url) as pub:
        for i in (1, 2, 2, 1, 3):
            pub.send(sample(i))
        got = collect(sub, 3, sample(3).time, limit=3.0)
        assert pub.flush()
    assert [s.sequence for s in got] == [1, 2, 3]
    assert sub.dropped == 2


def test_uadp_lockstep_fetch_waits_for_the_sender(uadp, url) -> None:
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=3.0) as sub, uadp.UadpLeadingValuePublisher(url) as pub:
        late = sample(500)
        timer = threading.Timer(0.2, pub.send, args=(late,))
        start = time.monotonic()
        timer.start()
        got = sub.fetch(late.time)
        waited = time.monotonic() - start
        timer.join()
    assert got == [late]
    assert 0.15 <= waited < 2.0
    assert not sub.sender_lost


def test_uadp_stopped_sender_costs_one_timeout_then_fetch_is_fast(uadp, url) -> None:
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=0.3) as sub:
        with uadp.UadpLeadingValuePublisher(url) as pub:
            for i in range(1, 4):
                pub.send(sample(i))
            assert collect(sub, 3, sample(3).time, limit=3.0) == [sample(i) for i in range(1, 4)]
        start = time.monotonic()                        # the sender is gone
        assert sub.fetch(sample(4).time) == []
        assert 0.25 <= time.monotonic() - start < 1.5
        assert sub.sender_lost
        for i in range(5, 25):
            start = time.monotonic()
            assert sub.fetch(sample(i).time) == []
            assert time.monotonic() - start < 0.05
        back = [sample(30, sequence=1), sample(31, sequence=2)]     # restarted: counts from 1 again
        with uadp.UadpLeadingValuePublisher(url) as pub:  # it comes back: lockstep resumes
            pub.send(back[0])
            assert collect(sub, 1, back[0].time, limit=3.0) == [back[0]]
            assert not sub.sender_lost
            timer = threading.Timer(0.1, pub.send, args=(back[1],))
            timer.start()
            start = time.monotonic()
            assert sub.fetch(back[1].time) == [back[1]]         # waits again
            assert time.monotonic() - start >= 0.05
            timer.join()
        assert sub.dropped == 0


def test_uadp_start_close_idempotent_and_threads_stop(uadp, url) -> None:
    before = set(threading.enumerate())
    pub = uadp.UadpLeadingValuePublisher(url)
    sub = uadp.UadpLeadingValueSubscriber(url, wait_timeout=0.2)
    pub.send(sample(1))                                 # queued before start, published after
    for _ in range(2):
        sub.start()
        pub.start()
    assert len(uadp_threads()) == 2
    assert collect(sub, 1, sample(1).time, limit=3.0) == [sample(1)]
    for _ in range(2):
        pub.close()
        sub.close()
    assert uadp_threads() == []
    assert {t for t in threading.enumerate() if not t.daemon} <= before
    start = time.monotonic()
    assert sub.fetch(1.0) == []                         # closed: returns at once
    assert time.monotonic() - start < 0.05
    pub.send(sample(2))                                 # ignored after close
    with pytest.raises(RuntimeError):
        pub.start()
    uadp.UadpLeadingValueSubscriber(url).close()        # never started


def test_uadp_close_wakes_a_waiting_fetch(uadp, url) -> None:
    sub = uadp.UadpLeadingValueSubscriber(url, wait_timeout=10.0)
    sub.start()
    closer = threading.Timer(0.1, sub.close)
    closer.start()
    start = time.monotonic()
    assert sub.fetch(1.0) == []
    assert time.monotonic() - start < 2.0
    closer.join()
    assert uadp_threads() == []


@pytest.mark.slow
def test_uadp_sustained_throughput(uadp, url) -> None:
    sent = [sample(i) for i in range(1, 20_001)]
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=10.0) as sub, uadp.UadpLeadingValuePublisher(url) as pub:
        start = time.monotonic()
        for s in sent:
            pub.send(s)
        got = collect(sub, len(sent), sent[-1].time, limit=25.0)
        elapsed = time.monotonic() - start
    assert got == sent
    assert len(sent) / elapsed > 2000
