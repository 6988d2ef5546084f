"""Imported first by the scripts run inside Blender: makes Debian's Blender 3.4 find numpy and the glTF add-on work.

Blender's own Python finds another installation first when one is on PATH (a pyenv), and that one may lack numpy:
Debian's is then added. Debian's numpy 1.24 dropped the numpy.bool alias that Blender 3.4's glTF add-on uses.
"""
import sys

try:
    import numpy
except ImportError:
    sys.path.append("/usr/lib/python3/dist-packages")
    import numpy

numpy.bool = bool
