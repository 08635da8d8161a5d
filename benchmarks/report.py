"""What the benchmark scripts' reports share: the renderer named in a `vct render --timings` file,
the short tag of a results file's name, reading the images vct writes (PFM), and writing the
report (also to stdout)."""
import datetime
import json
import struct
import sys


def renderer_of(timings_path):
    """The GL renderer string a `vct render --timings` JSON recorded, and its tag for file names."""
    renderer = json.load(open(timings_path))["renderer"]
    tag = "llvmpipe" if "llvmpipe" in renderer else renderer.split()[0].lower()
    return renderer, tag


def report_head(title, renderer, script, description, columns):
    """The lines every report starts with: its title, the renderer and date and the script that
    measured it with what it measures, and the head of its table (`columns`: the header cells)."""
    return [f"# {title}", "",
            f"Renderer: {renderer}, measured {datetime.date.today()} by `bash benchmarks/{script}`. {description}", "",
            "| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]


def write_report(path, lines):
    """Writes the markdown lines to `path`, prints them, and says where they went on stderr."""
    open(path, "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"wrote {path}", file=sys.stderr)


def read_pfm(path):
    """A PFM image as (width, height, pixels): RGB tuples, rows bottom to top as the file stores them."""
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        channels = 3 if kind == b"PF" else 1
        data = struct.unpack(("<" if scale < 0 else ">") + "f" * (width * height * channels), f.read())
    return width, height, [data[k:k + 3] if channels == 3 else (data[k],) * 3 for k in range(0, len(data), channels)]


def luminance(p):
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]
