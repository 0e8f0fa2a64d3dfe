"""UDP sockets for ``opc.udp://host:port`` URLs (OPC UA Part 14 §7.3.2, UADP over UDP).

The receiving socket binds the URL's own address, never the wildcard behind the user's back: a
subscriber of ``opc.udp://127.0.0.1:4840`` cannot be reached from another host.  It sets no
SO_REUSEADDR for a unicast address, so no other local socket can bind the same port and take its
datagrams (the bind fails instead: one receiver per unicast address and port).

A multicast URL (224.0.0.0/4, ff00::/8) is different: several subscribers on one host share the group,
which needs SO_REUSEADDR; that is the only place it is set.  The socket binds the group address (so it
sees only that group's datagrams on the port) and joins the group on ``interface`` (as a
PubSubConnection's NetworkInterface: the interface's name, e.g. ``eth0``, or for IPv4 its address;
default: the one the routing table picks).  The sender uses ``interface`` as its outgoing multicast interface, with ``ttl`` hops.
"""
from __future__ import annotations

import ipaddress
import socket
import struct
from dataclasses import dataclass
from urllib.parse import urlparse

__all__ = ["Endpoint", "parse_url", "receiver_socket", "sender_socket"]

DEFAULT_PORT = 4840


@dataclass(frozen=True)
class Endpoint:
    family: int
    address: tuple                  # sockaddr of the URL (host resolved)
    multicast: bool
    loopback: bool


def parse_url(url: str) -> Endpoint:
    """Resolve ``opc.udp://host[:port]``; ValueError naming the URL if it is not one."""
    if not isinstance(url, str):
        raise TypeError(f"URL must be a string like opc.udp://host:port, got {type(url).__name__}")
    try:
        parts = urlparse(url)
        port = parts.port if parts.port is not None else DEFAULT_PORT
    except ValueError as exc:
        raise ValueError(f"invalid URL {url!r}: {exc}") from None
    if parts.scheme != "opc.udp" or not parts.hostname:
        raise ValueError(f"URL must look like opc.udp://host:port, got {url!r}")
    try:
        family, _, _, _, addr = socket.getaddrinfo(parts.hostname, port, 0, socket.SOCK_DGRAM)[0]
    except socket.gaierror as exc:
        raise ValueError(f"cannot resolve the host of {url!r}: {exc}") from None
    ip = ipaddress.ip_address(addr[0])
    return Endpoint(family, addr, ip.is_multicast, ip.is_loopback)


def _mreq_v4(interface: str | None) -> bytes:
    """The interface part of an IPv4 membership/multicast-interface request: ``interface`` is the
    interface's address (ip_mreq) or its name, as a PubSubConnection's NetworkInterface (ip_mreqn)."""
    if not interface:
        return struct.pack("!I", socket.INADDR_ANY)
    try:
        return socket.inet_aton(str(ipaddress.IPv4Address(interface)))
    except ValueError:
        return struct.pack("!I", socket.INADDR_ANY) + struct.pack("@i", _index(interface))


def _index(interface: str | None) -> int:
    """Interface index for IPv6 multicast: a name (``eth0``) or a number; 0 lets the system choose."""
    if not interface:
        return 0
    if interface.isdigit():
        return int(interface)
    try:
        return socket.if_nametoindex(interface)
    except OSError:
        raise ValueError(f"no network interface named {interface!r}") from None


def receiver_socket(ep: Endpoint, interface: str | None = None, receive_buffer: int = 0) -> socket.socket:
    sock = socket.socket(ep.family, socket.SOCK_DGRAM)
    try:
        if receive_buffer:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, receive_buffer)
        if ep.multicast:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)     # share the group, see above
            if ep.family == socket.AF_INET:
                sock.bind(ep.address)
                sock.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP,
                                socket.inet_aton(ep.address[0]) + _mreq_v4(interface))
            else:
                sock.bind(ep.address)
                sock.setsockopt(socket.IPPROTO_IPV6, socket.IPV6_JOIN_GROUP,
                                socket.inet_pton(socket.AF_INET6, ep.address[0]) + struct.pack("@I", _index(interface)))
        else:
            sock.bind(ep.address)
    except BaseException:
        sock.close()
        raise
    return sock


def sender_socket(ep: Endpoint, interface: str | None = None, ttl: int | None = None) -> socket.socket:
    sock = socket.socket(ep.family, socket.SOCK_DGRAM)
    try:
        if ep.family == socket.AF_INET:
            if ep.multicast:
                if interface:
                    spec = _mreq_v4(interface)          # in_addr, or ip_mreqn without its group
                    sock.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_IF,
                                    spec if len(spec) == 4 else bytes(4) + spec)
                sock.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_LOOP, 1)
                if ttl is not None:
                    sock.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, ttl)
            local = ""
            if interface and not ep.multicast:      # unicast: send from that interface's address
                try:
                    local = str(ipaddress.IPv4Address(interface))
                except ValueError:
                    sock.setsockopt(socket.SOL_SOCKET, socket.SO_BINDTODEVICE, interface.encode())
            sock.bind((local, 0))
        else:
            if ep.multicast:
                if interface:
                    sock.setsockopt(socket.IPPROTO_IPV6, socket.IPV6_MULTICAST_IF, _index(interface))
                if ttl is not None:
                    sock.setsockopt(socket.IPPROTO_IPV6, socket.IPV6_MULTICAST_HOPS, ttl)
            sock.bind(("", 0))
    except BaseException:
        sock.close()
        raise
    return sock
