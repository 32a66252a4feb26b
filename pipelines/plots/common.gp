# Shared by the figure scripts: small readers of coolgas TSV tables.
# (Commands are joined with '.', not sprintf: gnuplot 5.4's sprintf cuts long
# strings, and file paths can be long.)
set encoding utf8
q(s) = "'" . s . "'"
# meta(file, key): the value of the first provenance line "# key: value".
meta(file, key) = system("sed -n " . q("s/^# " . key . ": //p") . " " . q(file) . " | head -n 1")
# tsvval(file, column): that column in the last data row (pipelines/tsv-value.sh);
# awk rewrites numbers such as 1e-05, which gnuplot's real() cannot read.
tsvval(file, col) = real(system("sh " . q(plots . "/../tsv-value.sh") . " " . q(file) . " " . q(col) . \
                                " | awk '{ printf \"%.17g\", $1 }'"))
# Blocks of a table whose block comments read '# t = T; key = value; ...':
# nblocks(file), and bfield(file, i, key), the value of key in the i-th one
# (its first word: 'beta = 1.3 +- 0.02 (...)' gives 1.3).
nblocks(f) = int(system("grep -c '^# t = ' " . q(f)))
bfield(f, i, key) = system("grep '^# t = ' " . q(f) . " | sed -n " . sprintf("%d", i) . "p | tr ';' '\\n' | sed -n " . \
                           q("s/^[# ]*" . key . " = //p") . " | cut -d' ' -f1")
