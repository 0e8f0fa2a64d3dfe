"""Leading values over OPC UA PubSub: UADP NetworkMessages (OPC UA Part 14 §7.2.2) over UDP (§7.3.2).

One sample travels as one NetworkMessage holding one DataSetMessage (variant encoding, the ten fields
of ``DATASET_FIELDS``), addressed by PublisherId, WriterGroupId and DataSetWriterId.  The messages are
written and read by ``uadp_codec`` (bounded, ``struct`` only) and secured by ``uadp_security``
(PubSub-Aes128-CTR / PubSub-Aes256-CTR with a shared key); the unsecured bytes are those asyncua's
PubSub publisher sends, so both ends interoperate with asyncua.  Each end runs one daemon thread on a
plain UDP socket (``udp``), so the servo cycle only touches a lock-protected queue.

Security default: a loopback URL needs nothing; any other address needs ``key=`` (signing and
encryption unless ``security="sign"``) or an explicit ``security="none"`` -- a leading value that any
host on the network can forge is not a silent default.  See docs/crossplc_security.md.

Pacing: UDP has no flow control, so the publisher sends at most ``max_rate`` samples per second
(default 5000), which a subscriber in the same process keeps up with.
"""
from __future__ import annotations

import logging
import math
import socket
import threading
import time
from collections import deque
from typing import Self

from plcmotion.kernel.leading_value import LeadingValueSample

from .sequence import SequenceWindow
from .uadp_codec import FIELDS, MAX_DATAGRAM, Codec, Rejected, validate
from .uadp_security import MODES, Security, generate_key
from .udp import Endpoint, parse_url, receiver_socket, sender_socket

__all__ = ["DATASET_FIELDS", "UadpLeadingValuePublisher", "UadpLeadingValueSubscriber", "generate_key"]

logger = logging.getLogger(__name__)

DEFAULT_URL = "opc.udp://127.0.0.1:4840"
#: The dataset: (field name, LeadingValueSample attribute), in telegram order.
DATASET_FIELDS: tuple[tuple[str, str], ...] = tuple((name, attr) for name, _, _, attr in FIELDS)

_STOP_TIMEOUT = 5.0          # wall seconds to join the background thread
_POLL = 0.05                 # wall seconds a blocked socket waits before looking at the stop flag
_BACKPRESSURE_TIMEOUT = 1.0  # longest a send() waits for room in a full queue
_RECEIVE_BUFFER = 4 << 20    # requested SO_RCVBUF of the subscriber (capped by net.core.rmem_max)
_MAX_RATE = 5000.0           # default publisher pacing, samples per wall second
_BURST = 20                  # samples a paced publisher may send at once after an idle spell
_MAX_INBOX = 100_000         # received samples kept for fetch; beyond, the oldest go


def _security(ep: Endpoint, url: str, security: str | None, key: bytes | None, token_id: int) -> Security | None:
    """The link's message security from the user's choice; see the module docstring for the default."""
    if security is None:
        if key is not None:
            security = "sign_encrypt"
        elif ep.loopback:
            security = "none"
        else:
            raise ValueError(f"{url}: a non-loopback address needs message security: pass key= (the same "
                             f"key data at publisher and subscriber, see generate_key) or opt out with "
                             f"security='none'")
    if security not in MODES:
        raise ValueError(f"security must be one of {MODES}, got {security!r}")
    if security == "none":
        if key is not None:
            raise ValueError("key= given with security='none': choose 'sign' or 'sign_encrypt', or drop the key")
        return None
    if key is None:
        raise ValueError(f"security={security!r} needs key= (see generate_key)")
    return Security(security, key, token_id)


MAX_WAIT = 60.0     # s: fetch runs in the servo cycle; a longer wait is a hung controller, not lockstep


def _wait_timeout(value: object) -> float:
    """``wait_timeout`` in [0, MAX_WAIT] s (NaN made fetch wait forever, a negative one gave up at once)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"wait_timeout must be a number of seconds, got {value!r}")
    if not 0.0 <= value <= MAX_WAIT:
        raise ValueError(f"wait_timeout must be in [0, {MAX_WAIT:g}] s, got {value!r}")
    return float(value)


def _source_address(source: object) -> str | None:
    """The sender address ``source`` resolved once (None: any sender)."""
    if source is None or source == "":
        return None
    if not isinstance(source, str):
        raise TypeError(f"source must be the sender's IP address as a string, got {source!r}")
    try:
        return socket.getaddrinfo(source, None)[0][4][0]
    except (socket.gaierror, UnicodeError) as exc:
        raise ValueError(f"source {source!r} is no address of a host: {exc}") from None


class _Worker:
    """One daemon thread running ``body(stop_event)``; start once, close idempotent."""

    def __init__(self, name: str) -> None:
        self.name = name
        self._lock = threading.Lock()
        self._thread: threading.Thread | None = None
        self.stop = threading.Event()
        self.closed = False

    @property
    def running(self) -> bool:
        return self._thread is not None and self._thread.is_alive() and not self.closed

    def start(self, body) -> bool:
        """Start ``body`` in the thread; False if already started; RuntimeError after close."""
        with self._lock:
            if self.closed:
                raise RuntimeError(f"{self.name} was closed; create a new one")
            if self._thread is not None:
                return False
            self._thread = threading.Thread(target=body, name=self.name, daemon=True)
            self._thread.start()
            return True

    def close(self) -> None:
        with self._lock:
            self.closed = True
            thread = self._thread
        self.stop.set()
        if thread is not None and thread is not threading.current_thread():
            thread.join(_STOP_TIMEOUT)


# ------------------------------------------------------------------------------------------- publisher

class UadpLeadingValuePublisher:
    """``LeadingValueSink`` publishing every sample as a UADP NetworkMessage to ``url``.

    ``send`` only queues the sample; a background thread publishes the queue in order, at most
    ``max_rate`` samples per wall second (None: as fast as it can, which may outrun a subscriber and
    lose datagrams).  If more than ``max_pending`` samples are queued, ``send`` waits for room, at most
    about a second, so a fast virtual-time sender is paced by the link instead of growing memory.
    Samples sent before ``start`` are kept and published once started.

    ``security``/``key``/``security_token_id``: message security, see the module docstring;
    ``interface``/``ttl``: outgoing interface address and hop limit for a multicast URL.
    """

    def __init__(self, url: str = DEFAULT_URL, publisher_id: int | str = 1, writer_group_id: int = 1,
                 dataset_writer_id: int = 1, name: str = "LeadingValue", max_pending: int = 10_000,
                 max_rate: float | None = _MAX_RATE, *, security: str | None = None, key: bytes | None = None,
                 security_token_id: int = 1, interface: str | None = None, ttl: int | None = None) -> None:
        self.url = url
        self._endpoint = parse_url(url)
        self.security = _security(self._endpoint, url, security, key, security_token_id)
        self._codec = Codec(publisher_id, writer_group_id, dataset_writer_id, self.security)
        self._interface, self._ttl = interface, ttl
        self._cond = threading.Condition()
        self._queue: deque[LeadingValueSample] = deque()
        self._max_pending = max_pending
        self._interval = 1.0 / max_rate if max_rate else 0.0
        self._worker = _Worker(f"uadp-pub-{name}")
        self._sock: socket.socket | None = None
        self.errors = 0     #: samples that could not be encoded or sent

    @property
    def pending(self) -> int:
        """Samples queued but not yet handed to the network."""
        with self._cond:
            return len(self._queue)

    def send(self, sample: LeadingValueSample) -> None:
        with self._cond:
            if self._worker.closed:
                return
            if len(self._queue) >= self._max_pending and self._worker.running:
                self._cond.wait_for(lambda: len(self._queue) < self._max_pending or self._worker.closed,
                                    _BACKPRESSURE_TIMEOUT)
            self._queue.append(sample)
            self._cond.notify_all()

    def flush(self, timeout: float = 1.0) -> bool:
        """Wait (at most ``timeout`` s) until every queued sample has been sent; True if so."""
        with self._cond:
            if not self._worker.running:
                return not self._queue
            return self._cond.wait_for(lambda: not self._queue, timeout)

    def start(self) -> None:
        """Open the socket and start publishing (idempotent); OSError if the socket cannot be opened."""
        if self._worker.running or self._worker.closed:
            self._worker.start(lambda: None)    # RuntimeError after close
            return
        self._sock = sender_socket(self._endpoint, self._interface, self._ttl)
        if not self._worker.start(self._run):
            self._sock.close()

    def _run(self) -> None:
        sock, addr, codec = self._sock, self._endpoint.address, self._codec
        assert sock is not None
        slot = -math.inf
        try:
            while True:
                with self._cond:
                    self._cond.wait_for(lambda: self._queue or self._worker.stop.is_set())
                    if self._worker.stop.is_set():
                        return
                    sample = self._queue[0]
                if self._interval:
                    now = time.monotonic()
                    if slot > now:
                        time.sleep(slot - now)
                    slot = max(slot, time.monotonic() - _BURST * self._interval) + self._interval
                try:
                    sock.sendto(codec.encode(sample), addr)
                except (TypeError, ValueError, OverflowError, AttributeError, OSError):
                    self.errors += 1    # logged once: a dead network must not flood the log at 1 kHz
                    (logger.exception if self.errors == 1 else logger.debug)(
                        "leading value sample not sent (further failures counted in .errors): %r", sample)
                with self._cond:
                    self._queue.popleft()
                    self._cond.notify_all()
        finally:
            sock.close()

    def close(self, drain_timeout: float = 1.0) -> None:
        """Publish what is queued (bounded by ``drain_timeout``), then stop (idempotent)."""
        if self._worker.running:
            self.flush(drain_timeout)
        with self._cond:
            self._worker.stop.set()
            self._cond.notify_all()
        self._worker.close()
        with self._cond:
            self._queue.clear()         # what did not go out in time is dropped
            self._cond.notify_all()

    def __enter__(self) -> Self:
        self.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


# ------------------------------------------------------------------------------------------ subscriber

class UadpLeadingValueSubscriber:
    """``LeadingValueSource`` receiving the samples of one DataSetWriter of one publisher.

    ``fetch(needed)`` returns the samples received since the previous call.  If the newest one is older
    than ``needed`` it first waits, at most ``wait_timeout`` wall seconds, for one that is not (lockstep
    with a sender running in virtual time).  After such a wait has timed out the sender counts as lost and
    ``fetch`` stops waiting until a new sample arrives, so the receiver keeps its pace and its proxy can
    detect the missing leading value.

    What is accepted (everything else is counted in ``rejected`` by reason and dropped):

    * datagrams from ``source`` (an IP address) if given, of at most 512 bytes, that decode as a
      telegram of the configured PublisherId / WriterGroupId / DataSetWriterId with the configured
      security (signature checked before the payload is read);
    * whose sequence number is within ``sequence_window`` ahead of the last one (see ``sequence``):
      duplicates and late ones count in ``dropped``; a restarted publisher is followed after
      ``resync_count`` consecutive numbers, or at once after the sender was lost;
    * whose time is finite and within +-1e12 s.  Other non-finite or out-of-range values make the
      sample invalid (``valid`` FALSE, values of the previous sample), counted in ``invalid``.
    """

    def __init__(self, url: str = DEFAULT_URL, publisher_id: int | str = 1, writer_group_id: int = 1,
                 dataset_writer_id: int = 1, wait_timeout: float = 1.0, name: str = "LeadingValue",
                 receive_buffer: int = _RECEIVE_BUFFER, *, security: str | None = None, key: bytes | None = None,
                 security_token_id: int = 1, source: str | None = None, interface: str | None = None,
                 sequence_window: int = 256, resync_count: int = 3) -> None:
        self.url = url
        self.wait_timeout = _wait_timeout(wait_timeout)
        self._endpoint = parse_url(url)
        self.security = _security(self._endpoint, url, security, key, security_token_id)
        self._codec = Codec(publisher_id, writer_group_id, dataset_writer_id, self.security)
        self._source = _source_address(source)
        self._interface = interface
        self._receive_buffer = receive_buffer
        self._window = SequenceWindow(sequence_window, resync_count)
        self._cond = threading.Condition()
        self._inbox: deque[LeadingValueSample] = deque(maxlen=_MAX_INBOX)
        self._newest_time = -math.inf
        self._last: LeadingValueSample | None = None
        self._sender_lost = False
        self._wanted = math.inf     # ``needed`` of a waiting fetch
        self._worker = _Worker(f"uadp-sub-{name}")
        self.accepted = 0   #: samples delivered
        self.dropped = 0    #: samples discarded as duplicate or late
        self.invalid = 0    #: samples delivered as invalid because of non-finite or out-of-range values
        self.rejected: dict[str, int] = {}  #: datagrams dropped, by reason

    @property
    def missed(self) -> int:
        """Samples never received (gaps in the sequence of accepted ones)."""
        return self._window.missed

    @property
    def resyncs(self) -> int:
        """Times the subscriber followed a publisher that restarted its count."""
        return self._window.resyncs

    @property
    def sender_lost(self) -> bool:
        """True after a wait timed out, until the next sample arrives."""
        with self._cond:
            return self._sender_lost

    def start(self) -> None:
        """Open the socket and start receiving (idempotent); OSError if the address cannot be bound."""
        if self._worker.running or self._worker.closed:
            self._worker.start(lambda: None)    # RuntimeError after close
            return
        sock = receiver_socket(self._endpoint, self._interface, self._receive_buffer)
        sock.settimeout(_POLL)
        if not self._worker.start(lambda: self._run(sock)):
            sock.close()

    def _run(self, sock: socket.socket) -> None:
        stop = self._worker.stop
        try:
            while not stop.is_set():
                try:
                    data, addr = sock.recvfrom(MAX_DATAGRAM + 1)
                except TimeoutError:
                    continue
                except OSError:
                    if stop.is_set():
                        return
                    logger.exception("%s: receive failed", self._worker.name)
                    time.sleep(_POLL)
                    continue
                self.receive(data, addr[0])
        finally:
            sock.close()

    def _reject(self, reason: str) -> None:
        count = self.rejected.get(reason, 0)
        if count == 0:      # one line per reason: a flood of garbage must not flood the log
            logger.warning("%s: datagram rejected (%s); further ones are counted in .rejected",
                           self._worker.name, reason)
        self.rejected[reason] = count + 1

    def receive(self, data: bytes, source: str | None = None) -> None:
        """Handle one datagram from ``source`` (what the receive thread does; public for testing)."""
        if self._source is not None and source != self._source:
            self._reject("source")
            return
        try:
            decoded = self._codec.decode(data)
        except Rejected as r:
            self._reject(r.reason)
            return
        with self._cond:
            sample = validate(decoded.values, self._last)
            if sample is None:
                self._reject("time")
                return
            if self._sender_lost:       # a restarted sender counts afresh
                self._window.restart()
            verdict = self._window.check(decoded.sequence)
            if verdict == "duplicate":
                self.dropped += 1
                return
            if verdict == "window":
                self._reject("window")
                return
            self.accepted += 1
            if not sample.valid and decoded.values[4]:
                self.invalid += 1
            self._last = sample
            self._inbox.append(sample)
            self._newest_time = max(self._newest_time, sample.time)
            self._sender_lost = False
            if sample.time >= self._wanted:
                self._cond.notify_all()

    def fetch(self, needed: float) -> list[LeadingValueSample]:
        if self._sender_lost and not self._inbox:
            return []   # lock-free while the sender is gone, so a fast receiver cannot starve receive
        with self._cond:
            if self._newest_time < needed and not self._sender_lost and self._worker.running:
                self._wanted = needed
                arrived = self._cond.wait_for(
                    lambda: self._newest_time >= needed or self._worker.stop.is_set(), self.wait_timeout)
                self._wanted = math.inf
                if not arrived:
                    self._sender_lost = True
            samples = list(self._inbox)
            self._inbox.clear()
        return samples

    def close(self) -> None:
        """Stop receiving and release the socket (idempotent); a waiting ``fetch`` returns at once."""
        with self._cond:
            self._worker.stop.set()
            self._cond.notify_all()
        self._worker.close()

    def __enter__(self) -> Self:
        self.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
