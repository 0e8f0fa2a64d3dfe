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

def test_crossplc_local_link_round_trip() -> None:
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

def test_crossplc_uadp_round_trip_is_complete_ordered_and_exact(uadp, url) -> None:
    rng = random.Random(7)
    # every finite value of the REAL range arrives bit-exact; inf and values beyond 1e12 make a sample
    # invalid (defect 9, see test_crossplc_uadp_non_finite_or_huge_values_arrive_as_invalid_samples_defect_9)
    specials = [0.0, -0.0, 1 / 3, math.pi, 5e-324, 1e12, -1e-300, -1e12]
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


def test_crossplc_uadp_ignores_other_writers(uadp, url) -> None:
    with uadp.UadpLeadingValueSubscriber(url, dataset_writer_id=1, wait_timeout=0.3) as sub, \
            uadp.UadpLeadingValuePublisher(url, dataset_writer_id=2) as other, \
            uadp.UadpLeadingValuePublisher(url, publisher_id=9, dataset_writer_id=1) as stranger:
        other.send(sample(1))
        stranger.send(sample(1))
        assert other.flush() and stranger.flush()
        assert sub.fetch(0.001) == []


def test_crossplc_uadp_drops_duplicate_and_out_of_order_sequences(uadp, url) -> None:
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=2.0) as sub, uadp.UadpLeadingValuePublisher(url) as pub:
        for i in (1, 2, 2, 1, 3):
            pub.send(sample(i))
        got = collect(sub, 3, sample(3).time, limit=3.0)
        assert pub.flush()
    assert [s.sequence for s in got] == [1, 2, 3]
    assert sub.dropped == 2


def test_crossplc_uadp_lockstep_fetch_waits_for_the_sender(uadp, url) -> None:
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


def test_crossplc_uadp_stopped_sender_costs_one_timeout_then_fetch_is_fast(uadp, url) -> None:
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


def test_crossplc_uadp_start_close_idempotent_and_threads_stop(uadp, url) -> None:
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


def test_crossplc_uadp_close_wakes_a_waiting_fetch(uadp, url) -> None:
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
def test_crossplc_uadp_sustained_throughput(uadp, url) -> None:
    sent = [sample(i) for i in range(1, 20_001)]
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=10.0) as sub, uadp.UadpLeadingValuePublisher(url) as pub:
        start = time.monotonic()
        for s in sent:
            pub.send(s)
        got = collect(sub, len(sent), sent[-1].time, limit=25.0)
        elapsed = time.monotonic() - start
    assert got == sent
    assert len(sent) / elapsed > 2000


# ------------------------------------------------------------ defect 9: binding, source, sequence, values

def _port(url: str) -> int:
    return int(url.rsplit(":", 1)[1])


def _raw_sender(address: str = "127.0.0.1") -> socket.socket:
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    s.bind((address, 0))
    return s


def _settle(sub, count: int, needed: float, limit: float = 3.0) -> list:
    return collect(sub, count, needed, limit)


def test_crossplc_uadp_subscriber_binds_the_url_address_not_the_wildcard_defect_9(uadp, url) -> None:
    """A subscriber of opc.udp://127.0.0.1:P does not receive what is sent to another address of the
    host (127.0.0.2 is loopback too): it binds the URL's address, not 0.0.0.0."""
    elsewhere = url.replace("127.0.0.1", "127.0.0.2")
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=0.3) as sub:
        with uadp.UadpLeadingValuePublisher(elsewhere) as pub:
            pub.send(sample(1))
            assert pub.flush()
        assert sub.fetch(sample(1).time) == []
        with uadp.UadpLeadingValuePublisher(url) as pub:
            pub.send(sample(2))
            assert _settle(sub, 1, sample(2).time) == [sample(2)]


def test_crossplc_uadp_no_other_local_socket_can_take_the_samples_defect_9(uadp, url) -> None:
    """No SO_REUSEADDR on a unicast subscriber: another socket (even one asking for address reuse) cannot
    bind its address and port, neither the same address nor the wildcard, so it cannot take its samples."""
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=2.0) as sub:
        for address in ("127.0.0.1", "0.0.0.0"):
            with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as thief:
                thief.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
                with pytest.raises(OSError):
                    thief.bind((address, _port(url)))
        with uadp.UadpLeadingValuePublisher(url) as pub:
            for i in range(1, 6):
                pub.send(sample(i))
            assert _settle(sub, 5, sample(5).time) == [sample(i) for i in range(1, 6)]
    with pytest.raises(OSError):       # and a second subscriber of the same address fails to start
        with uadp.UadpLeadingValueSubscriber(url) as one, uadp.UadpLeadingValueSubscriber(url):
            pass
    assert uadp_threads() == []


def test_crossplc_uadp_accepts_only_the_configured_source_address_defect_9(uadp, url) -> None:
    wire = pytest.importorskip("_uadp_wire")
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=0.5, source="127.0.0.1") as sub, \
            _raw_sender("127.0.0.2") as stranger, _raw_sender("127.0.0.1") as genuine:
        stranger.sendto(wire.datagram(sample(1)), ("127.0.0.1", _port(url)))
        genuine.sendto(wire.datagram(sample(2)), ("127.0.0.1", _port(url)))
        assert _settle(sub, 1, sample(2).time) == [sample(2)]
    assert sub.rejected == {"source": 1}


def test_crossplc_uadp_counts_and_drops_datagrams_of_other_ids_defect_9(uadp, url) -> None:
    """Only the configured PublisherId / WriterGroupId / DataSetWriterId are accepted; each other datagram
    is counted by reason."""
    wire = pytest.importorskip("_uadp_wire")
    with uadp.UadpLeadingValueSubscriber(url, publisher_id=5, writer_group_id=6, dataset_writer_id=7,
                                         wait_timeout=0.5) as sub, _raw_sender() as tx:
        to = ("127.0.0.1", _port(url))
        tx.sendto(wire.datagram(sample(1), 4, 6, 7), to)
        tx.sendto(wire.datagram(sample(1), 5, 9, 7), to)
        tx.sendto(wire.datagram(sample(1), 5, 6, 8), to)
        tx.sendto(b"\x01" * 600, to)                           # larger than any telegram
        tx.sendto(wire.datagram(sample(1), 5, 6, 7)[:-3], to)   # truncated
        tx.sendto(wire.datagram(sample(2), 5, 6, 7), to)
        assert _settle(sub, 1, sample(2).time) == [sample(2)]
    assert sub.rejected == {"publisher": 1, "group": 1, "writer": 1, "size": 1, "dataset": 1}
    assert sub.accepted == 1


def test_crossplc_uadp_forged_far_ahead_sequence_does_not_block_genuine_samples_defect_9(uadp, url) -> None:
    """One datagram with a sequence number far ahead is dropped (out of the window); the genuine samples
    after it are all delivered."""
    wire = pytest.importorskip("_uadp_wire")
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=1.0) as sub, _raw_sender() as tx:
        to = ("127.0.0.1", _port(url))
        for i in range(1, 6):
            tx.sendto(wire.datagram(sample(i)), to)
        tx.sendto(wire.datagram(sample(6, sequence=5 + 30_000, position=1e6)), to)
        for i in range(6, 11):
            tx.sendto(wire.datagram(sample(i)), to)
        got = _settle(sub, 10, sample(10).time)
    assert got == [sample(i) for i in range(1, 11)]
    assert sub.rejected == {"window": 1} and sub.missed == 0


def test_crossplc_uadp_publisher_restart_resynchronises_after_three_in_sequence_defect_9(uadp, url) -> None:
    """A publisher that restarts counting from 1 while the link is up: the first two numbers out of the
    window are dropped, from the third consecutive one on the subscriber follows the new count."""
    wire = pytest.importorskip("_uadp_wire")
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=1.0) as sub, _raw_sender() as tx:
        to = ("127.0.0.1", _port(url))
        for i in range(1000, 1004):
            tx.sendto(wire.datagram(sample(i)), to)
        for i, seq in enumerate(range(1, 6), start=1004):
            tx.sendto(wire.datagram(sample(i, sequence=seq)), to)
        got = _settle(sub, 7, sample(1008).time)
    assert [s.sequence for s in got] == [1000, 1001, 1002, 1003, 3, 4, 5]
    assert sub.resyncs == 1 and sub.rejected == {"window": 2}


def test_crossplc_uadp_sequence_window_wraps_at_65536_defect_9(uadp, url) -> None:
    """The DataSetMessage SequenceNumber is a UInt16: counting on across 65535 -> 0 is in sequence."""
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=2.0) as sub, uadp.UadpLeadingValuePublisher(url) as pub:
        sent = [sample(i) for i in range(65_533, 65_541)]
        for s in sent:
            pub.send(s)
        assert _settle(sub, len(sent), sent[-1].time) == sent
    assert sub.missed == 0 and sub.dropped == 0 and sub.rejected == {}


def test_crossplc_uadp_decoder_bomb_does_not_stall_the_subscriber_defect_9(uadp, url) -> None:
    """A 10-byte datagram that makes a general UADP decoder build a 16-million-element array is rejected
    before any decoding; the genuine sample sent right after it arrives at once."""
    wire = pytest.importorskip("_uadp_wire")
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=3.0) as sub, _raw_sender() as tx:
        to = ("127.0.0.1", _port(url))
        start = time.monotonic()
        tx.sendto(wire.null_array_bomb(1 << 24), to)
        tx.sendto(wire.datagram(sample(1)), to)
        assert sub.fetch(sample(1).time) == [sample(1)]
        assert time.monotonic() - start < 0.5            # asyncua's decoder: about 1 s CPU and 180 MB
    assert sub.rejected == {"unsupported": 1}


def test_crossplc_uadp_non_finite_or_huge_values_arrive_as_invalid_samples_defect_9(uadp, url) -> None:
    """Values that are not finite or beyond the REAL range (1e12) make the sample invalid (Valid FALSE)
    and are replaced by the previous sample's; a sample without a usable time is dropped."""
    good = sample(1, modulo_length=360.0, delay=0.004)
    wrong = {"position": math.nan, "velocity": -math.inf, "acceleration": 1e300, "modulo_length": -1.0,
             "delay": math.nan, "modulo_start": 2e12}
    bad = [sample(i, **{attr: value}) for i, (attr, value) in enumerate(wrong.items(), start=2)]
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=2.0) as sub, uadp.UadpLeadingValuePublisher(url) as pub:
        pub.send(good)
        for s in bad:
            pub.send(s)
        pub.send(sample(8, time=math.nan))
        pub.send(sample(9, time=1e300))
        pub.send(sample(10))
        got = _settle(sub, 8, sample(10).time)
    assert [s.sequence for s in got] == [1, 2, 3, 4, 5, 6, 7, 10]
    for previous, s, attr in zip(got, got[1:7], wrong):
        assert not s.valid
        assert getattr(s, attr) == getattr(previous, attr)
        assert all(math.isfinite(getattr(s, a)) for a in wrong)
    assert got[0] == good and got[-1] == sample(10)
    assert sub.invalid == 6 and sub.rejected == {"time": 2}


def test_crossplc_uadp_wire_format_matches_asyncua_pubsub(uadp) -> None:
    """The publisher's unsecured bytes are a UADP NetworkMessage that asyncua's PubSub decoder reads
    field for field, and the subscriber reads what asyncua's PubSub encoder writes (Part 14 §7.2.2)."""
    wire = pytest.importorskip("_uadp_wire")
    from plcmotion.crossplc.uadp_codec import Codec
    codec = Codec(0x0B0A, 2, 3)
    s = sample(70_000, valid=False, tracking=True, modulo_length=360.0, modulo_start=-1.5, delay=0.002)
    msg, back = wire.decode(codec.encode(s))
    assert back == s
    assert msg.Header.PublisherId == 0x0B0A and msg.GroupHeader.WriterGroupId == 2
    assert msg.DataSetPayloadHeader == [3] and msg.Payload[0].Header.SequenceNo == 70_000 & 0xFFFF
    decoded = codec.decode(wire.datagram(s, 0x0B0A, 2, 3))
    assert decoded.sequence == 70_000 & 0xFFFF
    assert codec.decode(codec.encode(s)) == decoded


def test_crossplc_uadp_network_address_needs_security_or_an_explicit_opt_out_defect_9(uadp) -> None:
    for url in ("opc.udp://192.0.2.10:4840", "opc.udp://239.0.0.1:4840"):
        for cls in (uadp.UadpLeadingValueSubscriber, uadp.UadpLeadingValuePublisher):
            with pytest.raises(ValueError, match="security='none'"):
                cls(url)
            cls(url, security="none").close()           # explicit opt-out: allowed (not started)
            assert cls(url, key=uadp.generate_key()).security.mode == "sign_encrypt"
    with pytest.raises(ValueError, match="opc.udp://host:port"):
        uadp.UadpLeadingValueSubscriber("udp://127.0.0.1:4840")


@pytest.mark.parametrize("interface", ["127.0.0.1", "lo"])
def test_crossplc_uadp_multicast_group_is_shared_by_two_subscribers_defect_9(uadp, interface) -> None:
    """A multicast URL: each subscriber joins the group on the given interface (its address or, as a
    PubSub NetworkInterface, its name) and both receive (the only case with address reuse)."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    group = f"opc.udp://239.255.77.{port % 250 + 1}:{port}"
    opts = {"security": "none", "interface": interface}
    try:
        a = uadp.UadpLeadingValueSubscriber(group, wait_timeout=1.0, **opts)
        b = uadp.UadpLeadingValueSubscriber(group, wait_timeout=1.0, **opts)
        a.start()
        b.start()
    except OSError as exc:
        pytest.skip(f"no multicast on loopback here: {exc}")
    try:
        with uadp.UadpLeadingValuePublisher(group, **opts) as pub:
            pub.send(sample(1))
            got_a, got_b = a.fetch(sample(1).time), b.fetch(sample(1).time)
        if not got_a and not got_b:
            pytest.skip("multicast datagrams are not looped back on this host")
        assert got_a == got_b == [sample(1)]
    finally:
        a.close()
        b.close()


def test_crossplc_uadp_ipv6_loopback_binds_its_address(uadp) -> None:
    try:
        with socket.socket(socket.AF_INET6, socket.SOCK_DGRAM) as probe:
            probe.bind(("::1", 0))
            port = probe.getsockname()[1]
    except OSError as exc:
        pytest.skip(f"no IPv6 loopback: {exc}")
    url = f"opc.udp://[::1]:{port}"
    with uadp.UadpLeadingValueSubscriber(url, wait_timeout=2.0) as sub, uadp.UadpLeadingValuePublisher(url) as pub:
        with socket.socket(socket.AF_INET6, socket.SOCK_DGRAM) as thief, pytest.raises(OSError):
            thief.bind(("::1", port))
        pub.send(sample(1))
        assert collect(sub, 1, sample(1).time, limit=3.0) == [sample(1)]


@pytest.mark.parametrize("kw, error", [
    ({"wait_timeout": math.nan}, ValueError), ({"wait_timeout": math.inf}, ValueError),
    ({"wait_timeout": -1.0}, ValueError), ({"wait_timeout": "1"}, TypeError), ({"wait_timeout": True}, TypeError),
    ({"source": "not an address"}, ValueError), ({"source": 5}, TypeError),
], ids=["timeout-nan", "timeout-inf", "timeout-negative", "timeout-text", "timeout-bool", "source-unresolvable",
        "source-not-text"])
def test_crossplc_uadp_subscriber_settings_are_checked_at_construction_defect_9(uadp, url, kw, error) -> None:
    """Review of issue 8: wait_timeout=nan made fetch() (called in the servo cycle) wait forever, a negative
    one counted the sender lost at once, a text one raised TypeError inside fetch(); a source that is no
    address gave socket.gaierror.  Each is a ValueError/TypeError naming the setting when constructed."""
    name = next(iter(kw))
    with pytest.raises(error, match=name):
        uadp.UadpLeadingValueSubscriber(url, **kw)


@pytest.mark.parametrize("bad", [5, None, b"opc.udp://127.0.0.1:4840"])
def test_crossplc_uadp_url_that_is_no_text_is_a_type_error_defect_9(uadp, bad) -> None:
    """Review of issue 8: a URL given as an int raised AttributeError from urllib."""
    with pytest.raises((TypeError, ValueError), match="URL"):
        uadp.UadpLeadingValueSubscriber(bad)
    with pytest.raises((TypeError, ValueError), match="URL"):
        uadp.UadpLeadingValuePublisher(bad)
