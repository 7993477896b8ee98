import sys

try:
    from xacro_compat.command import main
except ImportError as error:
    sys.exit("xacro: {} cannot import {} ({}); run the lab's scripts/setup".format(sys.executable, error.name, error))

main()
