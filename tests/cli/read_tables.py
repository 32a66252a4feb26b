"""Reads a coolgas table (data-schema/tsv-tables.md) with the readers users
reach for and prints, per reader, one line: its name, the column names it
found (comma-separated), the number of rows and the first column of the last
row. tests/cli/table_readers_test.cc compares them with coolgas's own reader.
Run with the Debian python3 (python3-numpy, python3-pandas)."""
import sys

import numpy
import pandas


def show(reader, names, rows, last):
    print(reader, ",".join(names), rows, repr(float(last)))


path = sys.argv[1]
frame = pandas.read_csv(path, sep="\t", comment="#")
show("pandas", frame.columns, len(frame), frame.iloc[-1, 0])
named = numpy.atleast_1d(numpy.genfromtxt(path, names=True))  # one row: 0-d
show("genfromtxt", named.dtype.names, len(named), named[-1][0])
plain = numpy.loadtxt(path, skiprows=1, ndmin=2)  # the recipe of data-schema/tsv-tables.md
show("loadtxt", ["-"], len(plain), plain[-1, 0])
