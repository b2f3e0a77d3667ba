"""`pip install ./python` (offline: `--no-index --no-build-isolation`): the essikit package with the native module
that the CMake build made (make native: build/native/python/essikit/_essikit*.so; ESSIKIT_BUILD names another build
folder). Nothing is compiled here."""
import glob
import os
import shutil

from setuptools import Distribution, setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))
VERSION = open(os.path.join(HERE, "..", "CMakeLists.txt")).read().split("project(essikit VERSION ")[1].split()[0]


class BuildWithNativeModule(build_py):
    def run(self):
        super().run()
        build = os.environ.get("ESSIKIT_BUILD", os.path.join(HERE, "..", "build", "native"))
        found = glob.glob(os.path.join(build, "python", "essikit", "_essikit*.so"))
        if not found:
            raise SystemExit(f"essikit: no native module _essikit*.so in {build}/python/essikit: build it first "
                             "(make native, with Debian's pybind11-dev), or set ESSIKIT_BUILD to the build folder")
        shutil.copy(found[0], os.path.join(self.build_lib, "essikit"))


class BinaryDistribution(Distribution):
    def has_ext_modules(self):
        return True


setup(name="essikit", version=VERSION, description="Check, trace and convert ESSI and EIA cutting tapes",
      packages=["essikit"], python_requires=">=3.9", cmdclass={"build_py": BuildWithNativeModule},
      distclass=BinaryDistribution)
