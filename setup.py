"""The CMake half of the subdivkit Python package (pyproject.toml has the metadata).

build_ext builds the extension module `_subdivkit` and libsubdiv with CMake, then lays out
a small installed tree inside the package, so that a wheel works on its own:

    subdivkit/_subdivkit.<abi>.so          the extension (RUNPATH $ORIGIN/<libdir>)
    subdivkit/<libdir>/libsubdiv*.so.*     the libraries
    subdivkit/<libdir>/subdivkit/plugins/  the example plugins
    subdivkit/share/subdivkit/schemes/     the built-in schemes (found from the library)

SUBDIVKIT_BUILD_DIR=<folder> reuses a configured CMake build (scripts/setup.sh's build/);
without it build/python-wheel is configured here (Release, no tests, no benchmarks).
"""
import os
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = Path(__file__).resolve().parent
(SOURCE_DIR / "build").mkdir(exist_ok=True)  # setuptools' work folders go there (below)


def run(*args):
    print("setup.py:", " ".join(map(str, args)), flush=True)
    subprocess.run([str(a) for a in args], check=True)


def cmake_cache_value(build_dir, name):
    for line in (build_dir / "CMakeCache.txt").read_text().splitlines():
        if line.startswith(name + ":"):
            return line.split("=", 1)[1]
    return ""


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = self.cmake_build_dir()
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        targets = ["subdivkit_python", "subdiv", "subdiv_circle_preserving", "subdiv_sqrt2", "subdiv_kobbelt_quad"]
        if cmake_cache_value(build_dir, "SUBDIV_HAVE_VTK") not in ("", "0", "OFF", "FALSE"):
            targets.append("subdiv_vtkio")
        run("cmake", "--build", build_dir, "-j", jobs, "--target", *targets)
        staging = Path(self.build_temp) / "cmake-install"
        shutil.rmtree(staging, ignore_errors=True)
        for component in ("python", "lib"):
            run("cmake", "--install", build_dir, "--prefix", staging, "--component", component)
        package = Path(self.get_ext_fullpath(ext.name)).parent
        package.mkdir(parents=True, exist_ok=True)
        modules = list(staging.glob("**/subdivkit/_subdivkit*.so"))
        if len(modules) != 1:
            raise RuntimeError(f"expected one _subdivkit module under {staging}, found {modules}")
        shutil.copy2(modules[0], self.get_ext_fullpath(ext.name))
        libdir = cmake_cache_value(build_dir, "CMAKE_INSTALL_LIBDIR") or "lib"
        for folder in (libdir, "share"):
            shutil.rmtree(package / folder, ignore_errors=True)
            shutil.copytree(staging / folder, package / folder, ignore=shutil.ignore_patterns("python3*"))
        # A wheel holds no symbolic links: keep each library once, under its soname (what
        # the extension asks the loader for), not also as lib*.so.X.Y.Z.
        for library in (package / libdir).glob("lib*.so.*.*.*"):
            soname = library.with_name(library.name.rsplit(".", 1)[0])
            if soname.exists():
                library.unlink()

    def cmake_build_dir(self):
        given = os.environ.get("SUBDIVKIT_BUILD_DIR")
        if given:
            build_dir = Path(given).resolve()
            if not (build_dir / "CMakeCache.txt").exists():
                raise RuntimeError(f"SUBDIVKIT_BUILD_DIR={given} is not a configured CMake build folder "
                                   "(run scripts/configure.sh, or leave SUBDIVKIT_BUILD_DIR unset)")
            python = cmake_cache_value(build_dir, "Python3_EXECUTABLE")
            if python and Path(python).resolve() != Path(sys.executable).resolve() and \
                    cmake_cache_value(build_dir, "Python3_VERSION") not in ("", sysconfig.get_python_version()):
                print(f"setup.py: note: {build_dir} builds the module for {python}", flush=True)
            return build_dir
        build_dir = SOURCE_DIR / "build" / "python-wheel"
        if not (build_dir / "CMakeCache.txt").exists():
            args = ["cmake", "-S", SOURCE_DIR, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                    "-DSUBDIV_BUILD_TESTS=OFF", "-DSUBDIV_BUILD_BENCH=OFF", "-DSUBDIV_BUILD_PARAVIEW_PLUGIN=OFF",
                    f"-DPython3_EXECUTABLE={sys.executable}"]
            if shutil.which("ninja"):
                args += ["-G", "Ninja"]
            if shutil.which("ccache"):
                args.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
            run(*args)
        return build_dir


setup(
    ext_modules=[Extension("subdivkit._subdivkit", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own work folders go inside the CMake build folder, not beside the sources.
    options={"build": {"build_base": "build/python-setuptools"},
             "egg_info": {"egg_base": "build"}},
)
