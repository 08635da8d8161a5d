"""What the benchmark scripts' reports share: the renderer named in a `vct render --timings` file,
the short tag of a results file's name, and writing the report (also to stdout)."""
import json
import sys


def renderer_of(timings_path):
    """The GL renderer string a `vct render --timings` JSON recorded, and its tag for file names."""
    renderer = json.load(open(timings_path))["renderer"]
    tag = "llvmpipe" if "llvmpipe" in renderer else renderer.split()[0].lower()
    return renderer, tag


def write_report(path, lines):
    """Writes the markdown lines to `path`, prints them, and says where they went on stderr."""
    open(path, "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"wrote {path}", file=sys.stderr)
