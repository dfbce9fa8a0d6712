# File names are bytes in UTF-8 on today's systems; a JVM under LANG=C (or POSIX) decodes the command line and
# encodes paths in ASCII, so a name like mesure-é.csv cannot even be named. Under a locale that is not UTF-8,
# the character set (LC_CTYPE) is switched to C.UTF-8 for moire's JVM; messages, dates and numbers are untouched.
case "${LC_ALL:-${LC_CTYPE:-${LANG:-}}}" in
  *[Uu][Tt][Ff]-8*|*[Uu][Tt][Ff]8*) ;;
  *) if [ -n "${LC_ALL:-}" ]; then export LANG="$LC_ALL"; unset LC_ALL; fi; export LC_CTYPE=C.UTF-8 ;;
esac
