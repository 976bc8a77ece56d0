"""The build backend of pyproject.toml (PEP 517): the wheel of the Python module.

CMake configures and builds the module for the Python running this backend, then
installs its `python` component (the module, its Python files and the plots and
scenes it carries: shockgas/app/files/data_dir.hpp) into a staging folder, which
is zipped as a wheel with its metadata (PEP 427, PEP 376 RECORD).

Environment:
  SHOCKGAS_WHEEL_BUILD_DIR  an existing CMake build folder to build in (and keep);
                            default: a temporary one
  CMAKE_BUILD_PARALLEL_LEVEL  the build's jobs (CMake's own variable)
"""
import base64
import hashlib
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        return re.search(r"project\(shockgas VERSION ([0-9.]+)", f.read()).group(1)


def _tag():
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{python}-{platform}"


def _metadata():
    return (f"Metadata-Version: 2.1\nName: shockgas\nVersion: {_version()}\n"
            "Summary: 1-D sticky and inelastic particle gas beside the inviscid Burgers equation\n"
            "Requires-Python: >=3.9\nRequires-Dist: numpy\n")


def _cmake(*args):
    subprocess.run(["cmake", *args], check=True, stdout=sys.stderr)


def _stage(build, staging):
    configure = ["-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DSHOCKGAS_BUILD_TESTS=OFF",
                 "-DSHOCKGAS_BUILD_BENCH=OFF", f"-DSHOCKGAS_PYTHON_EXECUTABLE={sys.executable}",
                 "-DSHOCKGAS_PYTHON_INSTALL_DIR=site"]
    if shutil.which("ccache"):
        configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        _cmake(*configure)
    _cmake("--build", build, "--target", "_shockgas")
    _cmake("--install", build, "--component", "python", "--prefix", staging)
    for folder, _, names in os.walk(staging):
        if os.path.basename(folder) == "shockgas" and "__init__.py" in names:
            return os.path.dirname(folder)
    raise RuntimeError(f"cmake --install --component python put no package into {staging}")


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def _write_wheel(site, wheel_directory):
    dist_info = f"shockgas-{_version()}.dist-info"
    name = f"shockgas-{_version()}-{_tag()}.whl"
    files = {}
    for folder, _, names in os.walk(os.path.join(site, "shockgas"), followlinks=True):
        for file in sorted(names):
            if file.endswith(".pyc"):
                continue
            path = os.path.join(folder, file)
            with open(path, "rb") as f:
                files[os.path.relpath(path, site)] = f.read()
    files[f"{dist_info}/METADATA"] = _metadata().encode()
    files[f"{dist_info}/WHEEL"] = (f"Wheel-Version: 1.0\nGenerator: shockgas_wheel\nRoot-Is-Purelib: false\n"
                                   f"Tag: {_tag()}\n").encode()
    record = [_record_line(n, d) for n, d in files.items()] + [f"{dist_info}/RECORD,,"]
    files[f"{dist_info}/RECORD"] = ("\n".join(record) + "\n").encode()
    with zipfile.ZipFile(os.path.join(wheel_directory, name), "w", zipfile.ZIP_DEFLATED) as wheel:
        for n, data in files.items():
            info = zipfile.ZipInfo(n, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if n.endswith(".so") else 0o644) << 16
            wheel.writestr(info, data, zipfile.ZIP_DEFLATED)
    return name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    kept = os.environ.get("SHOCKGAS_WHEEL_BUILD_DIR")
    with tempfile.TemporaryDirectory() as tmp:
        site = _stage(kept or os.path.join(tmp, "build"), os.path.join(tmp, "staging"))
        return _write_wheel(site, wheel_directory)


def get_requires_for_build_wheel(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    dist_info = os.path.join(metadata_directory, f"shockgas-{_version()}.dist-info")
    os.makedirs(dist_info, exist_ok=True)
    with open(os.path.join(dist_info, "METADATA"), "w") as f:
        f.write(_metadata())
    return os.path.basename(dist_info)
