#!/usr/bin/env python3
"""Sends head poses to a UDP port exactly as opentrack's "UDP over network" output does, for trying
`vroc play --realtime --head udp:port=PORT` without opentrack: one datagram per 4 ms (opentrack's
pipeline runs at 250 Hz, logic/pipeline.cpp), each six native-endian doubles x, y, z [cm] then yaw,
pitch, roll [deg] (proto-udp). The motion is a slow head sway: yaw +-20 deg and x +-5 cm at 0.5 Hz.

Usage: scripts/opentrack_send.py [--port 4242] [--host 127.0.0.1] [--seconds 10]
"""
import argparse
import math
import socket
import struct
import time


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--port", type=int, default=4242)
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--seconds", type=float, default=10.0)
    args = parser.parse_args()
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    period = 0.004
    start = time.monotonic()
    sent = 0
    while True:
        t = sent * period
        if t > args.seconds:
            break
        phase = 2 * math.pi * 0.5 * t
        pose = (5.0 * math.sin(phase), 0.0, 0.0, 20.0 * math.sin(phase), 0.0, 0.0)
        sock.sendto(struct.pack("=6d", *pose), (args.host, args.port))
        sent += 1
        delay = start + sent * period - time.monotonic()
        if delay > 0:
            time.sleep(delay)
    print(f"opentrack_send: {sent} datagrams in {time.monotonic() - start:.2f} s to {args.host}:{args.port}")


if __name__ == "__main__":
    main()
