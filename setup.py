"""`pip install .`: builds lancer's Python module and its command with CMake, and puts both in the wheel.

setuptools is the backend (pyproject.toml) because Debian has it (python3-setuptools, python3-wheel):
with `pip install --no-build-isolation` in a venv made with `--system-site-packages`, nothing comes
from the network. The extension is not compiled by setuptools: build_ext configures the CMake project
(Release, no tests, no benchmarks; MPI when CMake finds it) and builds only the `programs` target (the
CLI and the module), then copies the module into the package and the `lancer` program into the wheel's
scripts, so that the venv's bin/ has the native command itself (no Python start-up before each run).

Environment:
  LANCER_CMAKE_BUILD_DIR  an existing, configured CMake build folder to build and take the files from
                          instead of a fresh one (its options stay as they are; the tests use this)
  LANCER_CMAKE_ARGS       more CMake options for a fresh build, e.g. "-DLANCER_PORTABLE=ON -DLANCER_MPI=OFF"
  CMAKE_BUILD_PARALLEL_LEVEL  compile jobs (default: Ninja's, one per CPU and two more)
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

# setuptools' build_scripts is distutils' (setuptools ships its own copy).
from distutils.command.build_scripts import build_scripts  # noqa: E402  pylint: disable=wrong-import-order

SOURCE = Path(__file__).resolve().parent
BUILD_BASE = Path("build") / "pip"
# Where build_ext leaves the built program for build_scripts (relative to SOURCE, as setup() wants).
COMMAND = BUILD_BASE / "command" / "lancer"


def version():
    """The one version number: CMake's project(VERSION), as `lancer --version` prints it."""
    text = (SOURCE / "CMakeLists.txt").read_text()
    match = re.search(r"project\(lancer\s+VERSION\s+([0-9.]+)", text)
    if not match:
        sys.exit("lancer: setup.py found no project(lancer VERSION x.y.z) in CMakeLists.txt")
    return match.group(1)


def fail(message):
    # One line that pip shows among the backend's output; setuptools' traceback would bury it.
    sys.exit(f"lancer: {message}")


def missing_tools():
    tools = [tool for tool in ("cmake", "ninja") if shutil.which(tool) is None]
    compiler = shlex.split(os.environ.get("CXX", "c++"))[0]
    if shutil.which(compiler) is None:
        tools.append(f"a C++ compiler ({compiler})")
    return tools


class CMakeBuild(build_ext):
    """Builds the CMake project's `programs` and takes the extension module and the program from it."""

    def build_extension(self, ext):
        build_dir = self.cmake_build_dir()
        jobs = ["-j", os.environ["CMAKE_BUILD_PARALLEL_LEVEL"]] if os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") else []
        self.run_cmake(["--build", str(build_dir), "--target", "programs", *jobs],
                       f"the build in {build_dir} failed (its messages are above)")

        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        module = build_dir / "python" / "lancer" / f"_lancer{suffix}"
        if not module.is_file():
            built = sorted(p.name for p in (build_dir / "python" / "lancer").glob("_lancer*"))
            fail(f"{build_dir} has no python/lancer/_lancer{suffix} for {sys.executable} (found: "
                 f"{', '.join(built) or 'none'}); configure it with -DPython_EXECUTABLE={sys.executable} "
                 "-DLANCER_PYTHON=ON, or unset LANCER_CMAKE_BUILD_DIR")
        program = build_dir / "lancer"
        if not program.is_file():
            fail(f"{build_dir} has no lancer program after building `programs`")
        destination = Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(module, destination)
        command = SOURCE / COMMAND
        command.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(program, command)
        command.chmod(0o755)

    def cmake_build_dir(self):
        given = os.environ.get("LANCER_CMAKE_BUILD_DIR")
        if given:
            build_dir = Path(given).resolve()
            if not (build_dir / "CMakeCache.txt").is_file():
                fail(f"LANCER_CMAKE_BUILD_DIR={given} is not a configured CMake build folder (no CMakeCache.txt)")
            if shutil.which("cmake") is None:
                fail("cannot build: cmake not found (Debian: apt install cmake ninja-build g++)")
            return build_dir
        missing = missing_tools()
        if missing:
            fail(f"cannot build: {', '.join(missing)} not found; install them (Debian: apt install cmake "
                 "ninja-build g++, or run scripts/setup.sh, which installs every package lancer needs) and run pip again")
        build_dir = SOURCE / BUILD_BASE / "cmake"
        configure = ["-S", str(SOURCE), "-B", str(build_dir), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                     "-DLANCER_BUILD_TESTS=OFF", "-DLANCER_BUILD_BENCH=OFF", "-DLANCER_PYTHON=ON",
                     f"-DPython_EXECUTABLE={sys.executable}", *shlex.split(os.environ.get("LANCER_CMAKE_ARGS", ""))]
        if (build_dir / "CMakeCache.txt").is_file() and "Ninja" not in (build_dir / "CMakeCache.txt").read_text():
            shutil.rmtree(build_dir)  # another generator's folder cannot be reconfigured for Ninja
        self.run_cmake(configure, "CMake could not configure the build (its message is above); scripts/setup.sh "
                                  "installs the Debian packages lancer needs")
        return build_dir

    @staticmethod
    def run_cmake(arguments, failure):
        try:
            subprocess.run(["cmake", *arguments], check=True)
        except subprocess.CalledProcessError:
            fail(failure)


class CopyProgram(build_scripts):
    """The wheel's `lancer` script is the native program: copied as it is. distutils would open it as a
    Python script (to rewrite a #!python line) and fail on the binary."""

    def run(self):
        self.mkpath(self.build_dir)
        for script in self.scripts:
            target = os.path.join(self.build_dir, os.path.basename(script))
            self.copy_file(script, target)
            os.chmod(target, 0o755)


try:
    import wheel  # noqa: F401  setuptools before 70 builds wheels with it (bdist_wheel)
except ImportError:
    fail(f"cannot build a wheel: {sys.executable} has no wheel package (Debian: apt install python3-wheel, "
         "then make the venv from /usr/bin/python3 with --system-site-packages and pip install --no-build-isolation .)")

setup(
    version=version(),
    packages=["lancer"],
    package_dir={"": "python"},
    # Type stubs and the typing marker, when the package has them.
    package_data={"lancer": ["py.typed", "*.pyi"]},
    ext_modules=[Extension("lancer._lancer", sources=[])],
    scripts=[str(COMMAND)],
    cmdclass={"build_ext": CMakeBuild, "build_scripts": CopyProgram},
    options={"build": {"build_base": str(BUILD_BASE)}},
    zip_safe=False,
)
