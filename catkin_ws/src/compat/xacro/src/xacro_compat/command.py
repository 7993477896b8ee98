"""The `xacro` command of ROS 1, run by the PyPI xacro release (the ROS 2 line's code, which needs no ROS).

What differs between the two, and what `main` changes before handing over to xacro's own `main`:
- `$(find pkg)` (and `find('pkg')` inside `$(eval ...)`): the PyPI release asks the ament index, which only ROS 2
  has; here it resolves through the ROS package path as rospack does (see package_path).
- An unknown package is reported as "package 'name' not found ...", the way ROS 1's xacro words it, instead of a
  Python class name.
- Errors raised before xacro has parsed any XML (a missing input file) crash xacro 2.1.1's error handler, which
  names xml.parsers.expat without importing it; importing it here lets xacro report them as it reports the rest.
Unchanged, as the release does it: options (`--inorder`/`-i`, which Noetic launch files pass, is accepted and means
nothing: in-order processing is the only mode), `name:=value` arguments, `-o FILE`, `--deps`, warnings, and errors:
xacro's message and location on stderr, no traceback, exit status 2.
"""
import sys
import xml.parsers.expat  # noqa: F401  (see above: xacro's error handler needs it loaded)

import xacro
from xacro import substitution_args

from xacro_compat.package_path import PackageNotFound, PackagePaths


def use_package_path(paths):
    """Make xacro resolve packages with `paths` (a PackagePaths) for the rest of this process."""
    substitution_args._eval_find = paths.find
    substitution_args._eval_dict["find"] = paths.find
    expand = xacro.eval_extension

    def eval_extension(text):
        try:
            return expand(text)
        except xacro.XacroException as error:
            if isinstance(error.exc, PackageNotFound):
                raise xacro.XacroException(str(error.exc)) from None
            raise

    xacro.eval_extension = eval_extension


def main(argv=None):
    """Run xacro on `argv` (default: the command line) like ROS 1's `xacro` executable."""
    sys.argv[0] = "xacro"   # the name xacro's usage and option errors show
    if argv is not None:
        sys.argv[1:] = list(argv)
    use_package_path(PackagePaths())
    xacro.main()
