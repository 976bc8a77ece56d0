"""The container definitions of packaging/, checked as far as a machine without
Docker or Apptainer can: each parses (known instructions or sections, Debian 12
as base, the package installed and the command as entry point) and every file it
copies exists in the folder it is built from (the packages cpack wrote).

usage: check_containers.py PACKAGING_DIR PACKAGES_DIR
"""
import glob
import os
import sys

DOCKER_INSTRUCTIONS = {"FROM", "COPY", "RUN", "ENTRYPOINT", "CMD", "ENV", "ARG", "LABEL", "WORKDIR"}
APPTAINER_SECTIONS = {"%files", "%post", "%runscript", "%labels", "%environment", "%help", "%test"}


def docker_instructions(text):
    """(instruction, arguments) per logical line: continuations joined, comments dropped."""
    lines, current = [], ""
    for raw in text.splitlines():
        line = raw.strip()
        if not current and (not line or line.startswith("#")):
            continue
        current += " " + line.rstrip("\\").strip()
        if not line.endswith("\\"):
            word, _, rest = current.strip().partition(" ")
            lines.append((word, rest.strip()))
            current = ""
    return lines


def check_dockerfile(path, packages):
    lines = docker_instructions(open(path).read())
    problems = [f"unknown instruction {w}" for w, _ in lines if w not in DOCKER_INSTRUCTIONS]
    if lines[0] != ("FROM", "debian:12"):
        problems.append(f"first instruction {lines[0]} is not FROM debian:12")
    for word, rest in lines:
        if word == "COPY":
            *sources, _ = rest.split()
            problems += [f"COPY {s}: nothing in {packages} matches" for s in sources
                         if not glob.glob(os.path.join(packages, s))]
    if not any(w == "RUN" and "apt-get install" in r and "shockgas_" in r for w, r in lines):
        problems.append("the package is never installed")
    if ("ENTRYPOINT", '["shockgas"]') not in lines:
        problems.append("the entry point is not the command")
    return problems


def check_definition(path, packages):
    header, sections, current = {}, {}, None
    for raw in open(path).read().splitlines():
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        if line.startswith("%"):
            current = line.split()[0]
            sections[current] = []
        elif current is None:
            key, _, value = line.partition(":")
            header[key.strip()] = value.strip()
        else:
            sections[current].append(line)
    problems = [f"unknown section {s}" for s in sections if s not in APPTAINER_SECTIONS]
    if header.get("Bootstrap") != "docker" or header.get("From") != "debian:12":
        problems.append(f"header {header} is not Bootstrap: docker, From: debian:12")
    for line in sections.get("%files", []):
        source = line.split()[0]
        if not glob.glob(os.path.join(packages, source)):
            problems.append(f"%files {source}: nothing in {packages} matches")
    if not any("apt-get install" in l for l in sections.get("%post", [])):
        problems.append("%post never installs the package")
    if not any("shockgas" in l for l in sections.get("%runscript", [])):
        problems.append("%runscript does not run the command")
    return problems


def main():
    packaging, packages = sys.argv[1], sys.argv[2]
    problems = check_dockerfile(os.path.join(packaging, "Dockerfile"), packages)
    problems += check_definition(os.path.join(packaging, "shockgas.def"), packages)
    for p in problems:
        print(p)
    print("Dockerfile and shockgas.def:", "checked" if not problems else f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
