"""Report generators: the validation report (``viscocontact validate``) and the benchmark
harness (``viscocontact bench``).

They are applications of the library, kept beside it: they import the library, and nothing in
the library imports them (only the command line does, to run them).
"""
