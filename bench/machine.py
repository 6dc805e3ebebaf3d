"""The machine a benchmark ran on, for the line printed with its figures."""
import os


def machine():
    """CPU model and core count, e.g. "AMD EPYC, 2 cores"."""
    cpu = "unknown CPU"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    return f"{cpu}, {os.cpu_count()} cores"
