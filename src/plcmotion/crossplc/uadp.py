"""Leading values over OPC UA PubSub (UADP message mapping, UDP transport), built on ``asyncua.pubsub``.

The publisher is a regular asyncua PubSub application: a PublishedDataSet with the ten leading value
fields, one DataSetWriter, one WriterGroup and a UDP/UADP PubSubConnection.  Its data source hands the
writer group one queued sample per cycle of the group; with a publishing interval of 0 the group
therefore sends one NetworkMessage (holding one DataSetMessage, variant encoded) per sample, as soon as
the sample is queued, and sleeps while the queue is empty.  The subscriber is a ReaderGroup with one
DataSetReader whose SubscribedDataSet buffers the decoded samples for ``fetch``.  Each side runs its
asyncio loop in a daemon thread, so the servo cycle only touches a lock-protected queue.

Workarounds for asyncua 2.0/2.1 (confined to ``_connection`` and ``_PubSubThread``):

* ``PubSubConnection`` rebuilds its ``UdpSettings`` from the configuration, which always binds the
  socket to the *destination* port with SO_REUSEADDR.  For unicast on one host the publisher's socket
  then competes with the subscriber's for the datagrams (in practice the publisher, bound last, gets all
  of them and the subscriber none).  The settings object is therefore replaced after construction: the
  publisher binds an ephemeral port, the subscriber additionally gets a larger receive buffer.
* ``PubSubConnection.stop`` awaits its own cancelled reader/writer tasks, so the ``CancelledError``
  aborts it before the UDP transport is closed.  ``PubSub.stop`` runs it in a task and hides that; the
  leftover transport is closed here.
* ``PubSub.start`` swallows a failing ``PubSubConnection.start``; the socket is opened once up front so
  that a bad address raises from ``start()``.

Pacing: asyncua decodes a message more slowly (about 45 us) than it encodes one (about 33 us), and UDP
has no flow control, so an unpaced publisher overflows the subscriber's socket buffer within a few
hundred messages.  The publisher therefore sends at most ``max_rate`` samples per second (default
5000, lossless on loopback even with sender, receiver and both controllers in one process).

Batching several samples into one NetworkMessage is not done: asyncua builds one DataSetMessage per
DataSetWriter per publishing cycle, so batching would need several writers or array fields.
"""
from __future__ import annotations

import asyncio
import logging
import math
import socket
import threading
from collections import deque
from collections.abc import Awaitable, Callable, Sequence
from dataclasses import dataclass
from typing import Any, Self

from asyncua import pubsub, ua
from asyncua.pubsub.udp import UdpSettings

from plcmotion.kernel.leading_value import LeadingValueSample

__all__ = ["DATASET_FIELDS", "UadpLeadingValuePublisher", "UadpLeadingValueSubscriber"]

logger = logging.getLogger(__name__)

DEFAULT_URL = "opc.udp://127.0.0.1:4840"

#: The dataset: (field name, OPC UA built-in type, LeadingValueSample attribute), in telegram order.
DATASET_FIELDS: tuple[tuple[str, ua.VariantType, str], ...] = (
    ("Time", ua.VariantType.Double, "time"),
    ("Position", ua.VariantType.Double, "position"),
    ("Velocity", ua.VariantType.Double, "velocity"),
    ("Acceleration", ua.VariantType.Double, "acceleration"),
    ("Valid", ua.VariantType.Boolean, "valid"),
    ("Tracking", ua.VariantType.Boolean, "tracking"),
    ("ModuloLength", ua.VariantType.Double, "modulo_length"),
    ("ModuloStart", ua.VariantType.Double, "modulo_start"),
    ("Sequence", ua.VariantType.UInt32, "sequence"),
    ("DelayTime", ua.VariantType.Double, "delay"),
)
_CONVERT: dict[ua.VariantType, Callable[[Any], Any]] = {
    ua.VariantType.Double: float, ua.VariantType.Boolean: bool,
    ua.VariantType.UInt32: lambda v: int(v) & 0xFFFFFFFF}

_START_TIMEOUT = 5.0         # wall seconds for the background loop to open its socket
_STOP_TIMEOUT = 5.0          # wall seconds to join the background thread
_BACKPRESSURE_TIMEOUT = 1.0  # longest a send() waits for room in a full queue
_RECEIVE_BUFFER = 4 << 20    # requested SO_RCVBUF of the subscriber (capped by net.core.rmem_max)
_MAX_RATE = 5000.0           # default publisher pacing, samples per wall second
_BURST = 20                  # samples a paced publisher may send at once after an idle spell


# ---------------------------------------------------------------------------------------------- encoding

def _dataset_meta(name: str) -> pubsub.DataSetMeta:
    meta = pubsub.DataSetMeta.Create(ua.String(name))
    for field_name, vtype, _ in DATASET_FIELDS:
        meta.add_scalar(ua.String(field_name), vtype)
    return meta


def _encode(sample: LeadingValueSample) -> list[ua.DataValue]:
    return [ua.DataValue(ua.Variant(_CONVERT[vtype](getattr(sample, attr)), vtype))
            for _, vtype, attr in DATASET_FIELDS]


def _decode(fields: Sequence[pubsub.DataSetValue]) -> LeadingValueSample:
    values: dict[str, Any] = {f.Name: f.Value.Value.Value for f in fields}  # type: ignore[union-attr]
    return LeadingValueSample(**{attr: _CONVERT[vtype](values[name]) for name, vtype, attr in DATASET_FIELDS})


def _publisher_id(publisher_id: int | str) -> ua.Variant:
    if isinstance(publisher_id, str):
        return ua.Variant(publisher_id, ua.VariantType.String)
    return ua.Variant(ua.UInt32(publisher_id))


def _uint16(value: int, what: str) -> ua.UInt16:
    if not 0 < value <= 0xFFFF:
        raise ValueError(f"{what} must be 1..65535, got {value}")
    return ua.UInt16(value)


@dataclass
class _UdpSettings(UdpSettings):
    """asyncua's UDP settings plus a receive buffer size (0 keeps the system default)."""

    ReceiveBuffer: int = 0

    def create_socket(self) -> tuple[socket.socket, Any, Any]:
        sock, addr, local = super().create_socket()
        if self.ReceiveBuffer:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, self.ReceiveBuffer)
        return sock, addr, local


def _connection(name: str, publisher_id: ua.Variant, settings: _UdpSettings,
                **groups: Any) -> pubsub.PubSubConnection:
    sock, _, _ = settings.create_socket()   # raises OSError here instead of inside PubSub.start
    sock.close()
    con = pubsub.PubSubConnection.udp_uadp(name, publisher_id, settings, **groups)
    con._network_settings = settings        # see module docstring: asyncua would bind the destination port
    return con


# ----------------------------------------------------------------------------------------- loop thread

_Build = Callable[[], Awaitable[tuple[pubsub.PubSub, list[pubsub.PubSubConnection]]]]


class _PubSubThread:
    """Runs one asyncua PubSub application on its own event loop in a daemon thread."""

    def __init__(self, name: str, build: _Build) -> None:
        self._name = name
        self._build = build
        self._lock = threading.Lock()
        self._thread: threading.Thread | None = None
        self._ready = threading.Event()
        self._error: BaseException | None = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._stop: asyncio.Event | None = None
        self._closed = False

    @property
    def running(self) -> bool:
        return self._thread is not None and self._thread.is_alive() and not self._closed

    def start(self) -> None:
        with self._lock:
            if self._closed:
                raise RuntimeError(f"{self._name} was closed; create a new one")
            if self._thread is not None:
                return
            self._thread = threading.Thread(target=asyncio.run, args=(self._main(),), name=self._name,
                                            daemon=True)
            self._thread.start()
        if not self._ready.wait(_START_TIMEOUT):
            self.close()
            raise TimeoutError(f"{self._name} did not start within {_START_TIMEOUT} s")
        if self._error is not None:
            self.close()
            raise self._error

    def close(self) -> None:
        with self._lock:
            self._closed = True
            thread, loop, stop = self._thread, self._loop, self._stop
        if thread is None:
            return
        if loop is not None and stop is not None:
            try:
                loop.call_soon_threadsafe(stop.set)
            except RuntimeError:    # loop already closed
                pass
        if thread is not threading.current_thread():
            thread.join(_STOP_TIMEOUT)

    async def _main(self) -> None:
        with self._lock:    # close() either sees the loop or _main sees closed
            if self._closed:
                self._ready.set()
                return
            self._loop = asyncio.get_running_loop()
            self._stop = asyncio.Event()
        app: pubsub.PubSub | None = None
        connections: list[pubsub.PubSubConnection] = []
        try:
            app, connections = await self._build()
            await app.start()
            if any(con._transport is None for con in connections):
                raise OSError(f"{self._name}: asyncua could not open its UDP socket")
        except Exception as exc:
            self._error = exc
            if app is not None:
                await self._shutdown(app, connections)
            self._ready.set()
            return
        self._ready.set()
        try:
            await self._stop.wait()
        finally:
            await self._shutdown(app, connections)

    @staticmethod
    async def _shutdown(app: pubsub.PubSub, connections: list[pubsub.PubSubConnection]) -> None:
        await app.stop()
        for con in connections:     # asyncua 2.1.0 leaves them open, see module docstring
            if con._transport is not None:
                con._transport.close()
                con._transport = None


# ------------------------------------------------------------------------------------------- publisher

class _SampleFeed(pubsub.PubSubDataSource):
    """Queue between the servo thread (``put``) and the writer group, which takes one sample per message.

    With ``max_rate`` the feed hands out at most that many samples per wall second on average (after an
    idle spell up to ``_BURST`` at once): UDP has no flow control, and a subscriber slower than the
    publisher would otherwise overflow its socket buffer and lose samples.
    """

    def __init__(self, max_pending: int, max_rate: float | None) -> None:
        super().__init__()
        self._cond = threading.Condition()
        self._queue: deque[LeadingValueSample] = deque()
        self._max_pending = max_pending
        self._interval = 1.0 / max_rate if max_rate else 0.0
        self._slot = -math.inf      # loop time from which the next sample may go
        self._loop: asyncio.AbstractEventLoop | None = None
        self._waiter: asyncio.Future[None] | None = None
        self._accepting = True

    def __len__(self) -> int:
        with self._cond:
            return len(self._queue)

    def put(self, sample: LeadingValueSample) -> None:
        with self._cond:
            if not self._accepting:
                return
            if len(self._queue) >= self._max_pending and self._loop is not None:
                self._cond.wait_for(lambda: len(self._queue) < self._max_pending or not self._accepting,
                                    _BACKPRESSURE_TIMEOUT)
            self._queue.append(sample)
            waiter, self._waiter, loop = self._waiter, None, self._loop
        if waiter is not None and loop is not None:
            try:
                loop.call_soon_threadsafe(_wake, waiter)
            except RuntimeError:    # loop closed meanwhile
                pass

    def attach(self, loop: asyncio.AbstractEventLoop) -> None:
        """Bind the feed to the loop whose writer group takes the samples."""
        with self._cond:
            self._loop = loop if self._accepting else None

    def drain(self, timeout: float) -> bool:
        """Wait until the writer took every queued sample; False on timeout or if nobody is taking them."""
        with self._cond:
            if self._loop is None:
                return not self._queue
            return self._cond.wait_for(lambda: not self._queue, timeout)

    def shut(self) -> None:
        with self._cond:
            self._accepting = False
            self._loop = None
            self._cond.notify_all()

    async def on_get_value(self) -> list[ua.DataValue]:
        loop = asyncio.get_running_loop()
        while True:
            if self._interval and self._slot > loop.time():
                await asyncio.sleep(self._slot - loop.time())
            with self._cond:
                if self._queue:
                    sample = self._queue.popleft()
                    self._cond.notify_all()
                else:
                    sample, waiter = None, loop.create_future()
                    self._waiter = waiter
            if sample is None:
                await waiter
                continue
            if self._interval:
                self._slot = max(self._slot, loop.time() - _BURST * self._interval) + self._interval
            try:
                return _encode(sample)
            except (TypeError, ValueError, OverflowError):
                logger.exception("leading value sample cannot be encoded, dropped: %r", sample)


def _wake(waiter: asyncio.Future[None]) -> None:
    if not waiter.done():
        waiter.set_result(None)


class UadpLeadingValuePublisher:
    """``LeadingValueSink`` publishing every sample as a UADP NetworkMessage to ``url``.

    ``send`` only queues the sample; a background thread publishes the queue in order, at most
    ``max_rate`` samples per wall second (None: as fast as it can, which may outrun a subscriber and
    lose datagrams).  If more than ``max_pending`` samples are queued, ``send`` waits for room, at most
    about a second, so a fast virtual-time sender is paced by the link instead of growing memory.
    Samples sent before ``start`` are kept and published once started.
    """

    def __init__(self, url: str = DEFAULT_URL, publisher_id: int | str = 1, writer_group_id: int = 1,
                 dataset_writer_id: int = 1, name: str = "LeadingValue", max_pending: int = 10_000,
                 max_rate: float | None = _MAX_RATE) -> None:
        self.url = url
        self._feed = _SampleFeed(max_pending, max_rate)
        self._settings = _UdpSettings(Url=url, Adapter=(None, 0))    # ephemeral local port
        self._publisher_id = _publisher_id(publisher_id)
        self._writer_group_id = _uint16(writer_group_id, "writer_group_id")
        self._dataset_writer_id = _uint16(dataset_writer_id, "dataset_writer_id")
        self._name = name
        self._thread = _PubSubThread(f"uadp-pub-{name}", self._build)

    async def _build(self) -> tuple[pubsub.PubSub, list[pubsub.PubSubConnection]]:
        self._feed.attach(asyncio.get_running_loop())
        name = ua.String(self._name)
        dataset = pubsub.PublishedDataSet.Create(name, _dataset_meta(self._name), self._feed)
        writer = pubsub.DataSetWriter.new_uadp(name=name, dataset_name=name,
                                               dataset_writer_id=self._dataset_writer_id,
                                               message_timestamp=False, message_status=False)
        group = pubsub.WriterGroup.new_uadp(name=name, writer_group_id=self._writer_group_id,
                                            publishing_interval=ua.Duration(0), writer=[writer])
        con = _connection(f"{self._name} publisher", self._publisher_id, self._settings,
                          writer_groups=[group])
        app = pubsub.PubSub()
        await app.add_published_dataset(dataset)
        await app.add_connection(con)
        return app, [con]

    @property
    def pending(self) -> int:
        """Samples queued but not yet handed to the network."""
        return len(self._feed)

    def send(self, sample: LeadingValueSample) -> None:
        self._feed.put(sample)

    def flush(self, timeout: float = 1.0) -> bool:
        """Wait (at most ``timeout`` s) until every queued sample has been sent; True if so."""
        return self._feed.drain(timeout)

    def start(self) -> None:
        """Open the socket and start publishing (idempotent)."""
        self._thread.start()

    def close(self, drain_timeout: float = 1.0) -> None:
        """Publish what is queued (bounded by ``drain_timeout``), then stop (idempotent)."""
        if self._thread.running:
            self._feed.drain(drain_timeout)
        self._feed.shut()
        self._thread.close()

    def __enter__(self) -> Self:
        self.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


# ------------------------------------------------------------------------------------------ subscriber

class _Inbox:
    """asyncua SubscribedDataSet that decodes each received DataSetMessage and passes the sample on."""

    def __init__(self, deliver: Callable[[LeadingValueSample], None]) -> None:
        self._deliver = deliver

    async def on_dataset_received(self, meta: pubsub.DataSetMeta, fields: list[pubsub.DataSetValue]) -> None:
        try:
            sample = _decode(fields)
        except (KeyError, TypeError, ValueError, AttributeError):
            logger.warning("malformed leading value DataSetMessage dropped: %r", fields)
            return
        self._deliver(sample)

    async def on_state_change(self, meta: Any, state: ua.PubSubState) -> None:
        pass


def _is_newer(sequence: int, last: int) -> bool:
    """Sequence comparison with wrap-around at 2**32 (serial number arithmetic)."""
    return 0 < (sequence - last) % (1 << 32) < (1 << 31)


class UadpLeadingValueSubscriber:
    """``LeadingValueSource`` receiving the samples of one DataSetWriter of one publisher.

    ``fetch(needed)`` returns the samples received since the previous call.  If the newest one is older
    than ``needed`` it first waits, at most ``wait_timeout`` wall seconds, for one that is not (lockstep
    with a sender running in virtual time).  After such a wait has timed out the sender counts as lost and
    ``fetch`` stops waiting until a new sample arrives, so the receiver keeps its pace and its proxy can
    detect the missing leading value.  Samples whose sequence is not newer than the last one are dropped
    (except for the first one after the sender was lost: a restarted sender may count afresh).
    """

    def __init__(self, url: str = DEFAULT_URL, publisher_id: int | str = 1, writer_group_id: int = 1,
                 dataset_writer_id: int = 1, wait_timeout: float = 1.0, name: str = "LeadingValue",
                 receive_buffer: int = _RECEIVE_BUFFER) -> None:
        self.url = url
        self.wait_timeout = wait_timeout
        self._settings = _UdpSettings(Url=url, ReceiveBuffer=receive_buffer)
        self._publisher_id = _publisher_id(publisher_id)
        self._writer_group_id = _uint16(writer_group_id, "writer_group_id")
        self._dataset_writer_id = _uint16(dataset_writer_id, "dataset_writer_id")
        self._name = name
        self._cond = threading.Condition()
        self._inbox: list[LeadingValueSample] = []
        self._newest_time = -math.inf
        self._last_sequence: int | None = None
        self._sender_lost = False
        self._closed = False
        self._wanted = math.inf     # ``needed`` of a waiting fetch
        self.dropped = 0    #: samples discarded as duplicate or out of order
        self.missed = 0     #: samples never received (gaps in the sequence)
        self._thread = _PubSubThread(f"uadp-sub-{name}", self._build)

    async def _build(self) -> tuple[pubsub.PubSub, list[pubsub.PubSubConnection]]:
        reader = pubsub.DataSetReader.new(self._publisher_id, self._writer_group_id, self._dataset_writer_id,
                                          _dataset_meta(self._name), name=self._name, enabled=True,
                                          subscribed=_Inbox(self._receive))  # type: ignore[arg-type]
        group = pubsub.ReaderGroup.new(name=self._name, reader=[reader], enable=True)
        con = _connection(f"{self._name} subscriber", self._publisher_id, self._settings,
                          reader_groups=[group])
        app = pubsub.PubSub()
        await app.add_connection(con)
        return app, [con]

    @property
    def sender_lost(self) -> bool:
        """True after a wait timed out, until the next sample arrives."""
        with self._cond:
            return self._sender_lost

    def _receive(self, sample: LeadingValueSample) -> None:
        with self._cond:
            last = self._last_sequence
            if last is not None and not self._sender_lost:  # after a loss: a restarted sender counts afresh
                if not _is_newer(sample.sequence, last):
                    self.dropped += 1
                    return
                self.missed += (sample.sequence - last - 1) % (1 << 32)
            self._last_sequence = sample.sequence
            self._inbox.append(sample)
            self._newest_time = max(self._newest_time, sample.time)
            self._sender_lost = False
            if sample.time >= self._wanted:
                self._cond.notify_all()

    def fetch(self, needed: float) -> list[LeadingValueSample]:
        if self._sender_lost and not self._inbox:
            return []   # lock-free while the sender is gone, so a fast receiver cannot starve _receive
        with self._cond:
            if self._newest_time < needed and not self._sender_lost and not self._closed \
                    and self._thread.running:
                self._wanted = needed
                arrived = self._cond.wait_for(lambda: self._newest_time >= needed or self._closed,
                                              self.wait_timeout)
                self._wanted = math.inf
                if not arrived:
                    self._sender_lost = True
            samples, self._inbox = self._inbox, []
        return samples

    def start(self) -> None:
        """Open the socket and start receiving (idempotent)."""
        self._thread.start()

    def close(self) -> None:
        """Stop receiving and release the socket (idempotent); a waiting ``fetch`` returns at once."""
        with self._cond:
            self._closed = True
            self._cond.notify_all()
        self._thread.close()

    def __enter__(self) -> Self:
        self.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
