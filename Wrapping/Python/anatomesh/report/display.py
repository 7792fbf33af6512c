"""An X display for VTK's rendering: the one the user has, or an Xvfb started for the report.

ParaView's VTK renders through GLX only (no EGL or OSMesa), and creating a render window
without an X server crashes: the report checks first and renders nothing rather than crash.
"""
import contextlib
import os
import select
import shutil
import subprocess


@contextlib.contextmanager
def x_display(timeout=20.0):
    """Yields the reason no picture can be drawn, or None when VTK can render (DISPLAY set, or an
    Xvfb started here and stopped on exit)."""
    if os.environ.get("DISPLAY"):
        yield None
        return
    xvfb = shutil.which("Xvfb")
    if xvfb is None:
        yield "no X display (DISPLAY is not set) and no Xvfb to start (Debian package xvfb)"
        return
    read_end, write_end = os.pipe()
    # -displayfd: Xvfb picks a free display number and writes it once it accepts connections.
    proc = subprocess.Popen([xvfb, "-displayfd", str(write_end), "-screen", "0", "1600x1200x24", "-nolisten", "tcp"],
                            pass_fds=(write_end,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_end)
    number = b""
    try:
        while not number.endswith(b"\n"):
            ready, _, _ = select.select([read_end], [], [], timeout)
            chunk = os.read(read_end, 16) if ready else b""
            if not chunk:
                break
            number += chunk
    finally:
        os.close(read_end)
    if not number.strip().isdigit():
        proc.kill()
        proc.wait()
        yield "Xvfb did not start"
        return
    os.environ["DISPLAY"] = ":" + number.strip().decode()
    try:
        yield None
    finally:
        del os.environ["DISPLAY"]
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
