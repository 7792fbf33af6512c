"""Text files that appear whole or not at all."""
import os


def write_text(path, text):
    """Write text under a temporary name beside path, flushed to disk, then renamed over it; on an
    error (a full disk) no temporary file stays behind."""
    tmp = path + ".tmp%d" % os.getpid()
    try:
        with open(tmp, "w") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
