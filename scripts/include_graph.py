#!/usr/bin/python3
"""The include graph of heavesim's source tree, by folder, and the layering it must keep.

    scripts/include_graph.py               list every folder-to-folder include edge
    scripts/include_graph.py --dot         the same as a Graphviz digraph (dot -Tpng)
    scripts/include_graph.py --check       exit 1 if any edge goes from a lower layer to a
                                           higher one, or a forbidden construct appears

Layers, lowest first (docs/architecture.md): a file may include from its own folder and
from lower layers only. Folders on one line of LAYERS are peers and may not include each
other either. Inside kernel/ the same rule holds between its sub-folders (KERNEL_LAYERS).
tests/ and bench/ sit above everything and are not checked.
"""
import argparse
import collections
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent

# Top-level libraries, lowest first; a tuple holds peers.
LAYERS = [
    ("kernel",),
    ("hydro", "control", "samples", "signal"),
    ("io",),
    ("app",),
    ("validation",),
    ("cli",),
    ("python",),  # the Python package's module: calls the commands, as the executable does
]
# validation/oracles are the independent references: Eigen and SUNDIALS only.
ISOLATED = {"validation/oracles"}
# kernel/ sub-folders, lowest first.
KERNEL_LAYERS = [
    ("kernel/.",),  # files directly in kernel/ (parameter_error.hpp): the vocabulary every layer uses
    ("kernel/spatial",),
    ("kernel/math",),
    ("kernel/complementarity",),
    ("kernel/joints",),
    ("kernel/model",),
    ("kernel/algorithms",),
    ("kernel/elements",),
    ("kernel/contact",),
    ("kernel/system",),
    ("kernel/integrators",),
    ("kernel/analysis",),
]
# Constructs that must not appear in a folder: (folder prefixes, regex, why).
FORBIDDEN = [
    (("kernel/integrators", "app/output"), re.compile(r"\bdynamic_cast\b"),
     "integrators and summaries are bound to what they need at compile time"),
    (("kernel", "hydro", "control"), re.compile(r"throw\s+std::invalid_argument"),
     "domain rules throw ParameterError, which the application maps to the case key"),
]

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
SOURCE_SUFFIXES = {".hpp", ".cpp", ".h", ".cc"}


def layer_index(folder, layers):
    for index, peers in enumerate(layers):
        for name in peers:
            if folder == name or folder.startswith(name + "/"):
                return index, name
    return None, None


def folder_of(relative_path, depth):
    """The file's folder, `depth` levels deep; "kernel/." for a file directly in kernel/."""
    parts = pathlib.PurePosixPath(relative_path).parts[:-1]
    if len(parts) < depth and parts and parts[0] == "kernel":
        return "kernel/."
    return "/".join(parts[:depth])


def source_files():
    for top in sorted({name for peers in LAYERS for name in peers}):
        base = ROOT / top
        if base.is_dir():
            for path in sorted(base.rglob("*")):
                if path.suffix in SOURCE_SUFFIXES:
                    yield path.relative_to(ROOT).as_posix()


def edges():
    """(from folder, to folder) -> list of (file, included header), two levels deep."""
    found = collections.defaultdict(list)
    for relative in source_files():
        text = (ROOT / relative).read_text(errors="replace")
        for header in INCLUDE.findall(text):
            if not (ROOT / header).exists():
                continue  # a generated or sibling-relative header (e.g. app/version.hpp)
            source_folder = folder_of(relative, 2)
            target_folder = folder_of(header, 2)
            if source_folder != target_folder:
                found[(source_folder, target_folder)].append((relative, header))
    return found


def violations(found):
    problems = []
    for (source, target), sites in sorted(found.items()):
        reason = None
        if any(source == o or source.startswith(o + "/") for o in ISOLATED):
            reason = "the oracles include nothing of the project"
        else:
            source_layer, source_name = layer_index(source, LAYERS)
            target_layer, target_name = layer_index(target, LAYERS)
            if source_layer is not None and target_layer is not None:
                if target_layer > source_layer:
                    reason = f"{target_name}/ is above {source_name}/"
                elif target_layer == source_layer and source_name != target_name:
                    reason = f"{source_name}/ and {target_name}/ are peers"
            if reason is None and source.startswith("kernel/") and target.startswith("kernel/"):
                source_sub, _ = layer_index(source, KERNEL_LAYERS)
                target_sub, _ = layer_index(target, KERNEL_LAYERS)
                if source_sub is None or target_sub is None:
                    reason = "a kernel folder missing from KERNEL_LAYERS"
                elif target_sub > source_sub:
                    reason = f"{target} is above {source} inside kernel/"
        if reason:
            file, header = sites[0]
            more = f" (+{len(sites) - 1} more)" if len(sites) > 1 else ""
            problems.append(f"{source} -> {target}: {reason}: {file} includes {header}{more}")
    for relative in source_files():
        for prefixes, pattern, why in FORBIDDEN:
            if any(relative.startswith(p + "/") for p in prefixes):
                text = (ROOT / relative).read_text(errors="replace")
                for match in pattern.finditer(text):
                    line = text.count("\n", 0, match.start()) + 1
                    problems.append(f"{relative}:{line}: '{match.group(0)}': {why}")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--dot", action="store_true", help="print a Graphviz digraph")
    parser.add_argument("--check", action="store_true", help="exit 1 on a layering violation")
    arguments = parser.parse_args()
    found = edges()
    if arguments.dot:
        print("digraph heavesim {\n  rankdir=BT;")
        for (source, target), sites in sorted(found.items()):
            print(f'  "{source}" -> "{target}" [label="{len(sites)}"];')
        print("}")
    elif not arguments.check:
        for (source, target), sites in sorted(found.items()):
            print(f"{source:24s} -> {target:24s} {len(sites):3d} includes")
    if arguments.check:
        problems = violations(found)
        for problem in problems:
            print(problem)
        print(f"include graph: {len(found)} folder edges, {len(problems)} violations")
        return 1 if problems else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
