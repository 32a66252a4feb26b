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

# term(w, h): the terminal command for `out`: pdfcairo if it ends in .pdf
# (w, h in pixels at 100 per inch), else pngcairo. Use: eval term(1800, 600)
is_pdf(f) = strlen(f) > 4 && f[strlen(f) - 3:strlen(f)] eq ".pdf"
term(w, h) = is_pdf(out) ? sprintf("set terminal pdfcairo enhanced size %.2fin,%.2fin font 'sans,10'", w / 100.0, h / 100.0) \
                         : sprintf("set terminal pngcairo enhanced size %d,%d font 'sans,11'", w, h)
# Line styles 1-8: colour, dash and point type all differ, so curves stay
# apart in grey print too. Curves use 'ls i' and 'pi 6' (a point every 6 rows).
array style_rgb[8] = ["#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#000000", "#999999"]
array style_pt[8] = [7, 5, 9, 11, 13, 4, 6, 8]
do for [i = 1:8] {
  eval sprintf("set style line %d lc rgb '%s' dt %d pt %d ps 0.9 lw 2", i, style_rgb[i], i <= 5 ? i : i - 5, style_pt[i])
}
