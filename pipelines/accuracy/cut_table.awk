# cut_table.awk: a coolgas table (first column t) as if its run had ended at
# t = t_cut (awk -v t_cut=T -v why=TEXT): the column line, the provenance,
# a '# t_cut: T (TEXT)' line saying why later rows are missing, and the data
# rows with t <= T (block comments and blank lines kept).
NR == 1 { print; next }
/^#/ && !data { print; next }
!data { print "# t_cut: " t_cut " (" why ")"; data = 1 }
/^#/ || NF == 0 { print; next }
$1 + 0 <= t_cut + 0 { print }
