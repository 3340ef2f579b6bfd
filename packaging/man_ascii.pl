#!/usr/bin/perl
# SPDX-License-Identifier: MIT
# A man page in ASCII: every other character written as groff's \[uXXXX], which man shows as the character in a
# UTF-8 terminal and as its nearest ASCII elsewhere (help2man's UTF-8 en dash showed as ??? in a C locale).
#   perl man_ascii.pl IN.utf8 OUT
use strict;
use warnings;
my ($in, $out) = @ARGV;
open(my $from, '<:encoding(UTF-8)', $in) or die "man_ascii: cannot read $in: $!\n";
open(my $to, '>', $out) or die "man_ascii: cannot write $out: $!\n";
while (my $line = <$from>) {
    $line =~ s/([^\x00-\x7f])/sprintf('\\[u%04X]', ord($1))/ge;
    print $to $line;
}
close($to) or die "man_ascii: cannot write $out: $!\n";
