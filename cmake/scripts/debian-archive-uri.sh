# shellcheck shell=sh
# Sourced by cmake/scripts/fetch-debian-source.sh and cmake/scripts/fetch-debian-deb.sh:
# system_archive_uri prints the Debian archive URI of the system's own apt
# sources, so that no package host is named in POLYDEM's code; debian_mirror,
# the archive the scripts fetch from.
#
# the archive URI the system's apt already uses for its main suite (the
# suite named VERSION_CODENAME in /etc/os-release; else the first deb suite
# without a -updates/-security tail): apt's own reading of its sources, then
# the sources files themselves
system_archive_uri() {
  codename=
  if [ -r /etc/os-release ]; then
    codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  fi
  targets=$(apt-get indextargets --format '$(TARGET_OF) $(REPO_URI) $(RELEASE)' 2> /dev/null |
    awk '$1 == "deb" { print $2, $3 }' | sort -u) || targets=
  if [ -z "$targets" ]; then
    # deb822 stanzas: Types / URIs / Suites, one stanza per blank-line block
    targets=$(cat /etc/apt/sources.list.d/*.sources 2> /dev/null | awk '
      function flush() { if (types ~ /(^| )deb( |$)/) for (i = 1; i <= nu; i++) for (j = 1; j <= ns; j++) print u[i], s[j]; types = ""; nu = ns = 0 }
      /^[ \t]*$/ { flush(); next }
      /^[ \t]*#/ { next }
      tolower($1) == "types:" { types = ""; for (i = 2; i <= NF; i++) types = types " " $i; types = types " " }
      tolower($1) == "uris:" { for (i = 2; i <= NF; i++) u[++nu] = $i }
      tolower($1) == "suites:" { for (i = 2; i <= NF; i++) s[++ns] = $i }
      END { flush() }')
    # one-line format: deb [options] URI SUITE COMPONENT...
    targets="$targets
$(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2> /dev/null | awk '
      $1 == "deb" { i = 2; if ($i ~ /^\[/) { while ($i !~ /\]$/) i++; i++ } print $i, $(i + 1) }')"
  fi
  echo "$targets" | awk -v c="$codename" '
    NF == 2 && c != "" && $2 == c && !hit { hit = $1 }
    NF == 2 && $2 !~ /-/ && !first { first = $1 }
    END { if (hit) print hit; else if (first) print first }'
}

# debian_mirror NAME: the archive URI to fetch from, without a trailing slash:
# POLYDEM_DEBIAN_MIRROR, else the system's own (system_archive_uri). Where
# there is none, says so on stderr (NAME: the calling script) and returns 1.
debian_mirror() {
  mirror=${POLYDEM_DEBIAN_MIRROR:-}
  if [ -z "$mirror" ]; then
    mirror=$(system_archive_uri)
    if [ -z "$mirror" ]; then
      echo "$1: no Debian archive in the system's apt sources; set POLYDEM_DEBIAN_MIRROR" >&2
      return 1
    fi
  fi
  printf '%s\n' "${mirror%/}"
}

# private_apt_init NAME TYPE DIR SUITE: an apt configuration of its own under
# DIR/.apt: one sources file of TYPE (deb or deb-src) for SUITE of
# debian_mirror's archive, signed by Debian's archive keyring, its own lists
# and cache, an empty dpkg status (so that the system's sources, cache, locks
# and installed packages play no part); then apt-get update. NAME: the calling
# script, for messages. Returns 1 where the keyring or the archive is missing.
private_apt_init() {
  keyring=/usr/share/keyrings/debian-archive-keyring.gpg
  if [ ! -r "$keyring" ]; then
    echo "$1: $keyring missing (apt-get install debian-archive-keyring)" >&2
    return 1
  fi
  mirror=$(debian_mirror "$1") || return 1
  private_apt_dir=$3/.apt
  sources=polydem.sources
  [ "$2" = deb-src ] && sources=polydem-src.sources
  mkdir -p "$private_apt_dir/sources.list.d" "$private_apt_dir/lists/partial" \
    "$private_apt_dir/cache/archives/partial"
  cat > "$private_apt_dir/sources.list.d/$sources" << EOF
Types: $2
URIs: $mirror
Suites: $4
Components: main
Signed-By: $keyring
EOF
  echo "$1: apt-get update (private $2 list: $mirror $4)" >&2
  private_apt -q update >&2
}

# private_apt ARGS...: apt-get ARGS with private_apt_init's configuration
# (as root without apt's _apt sandbox user, which cannot write into a user's
# directory)
private_apt() {
  if [ "$(id -u)" = 0 ]; then
    set -- -o APT::Sandbox::User=root "$@"
  fi
  apt-get -o Dir::Etc::SourceList=/dev/null \
    -o Dir::Etc::SourceParts="$private_apt_dir/sources.list.d" \
    -o Dir::State::Lists="$private_apt_dir/lists" \
    -o Dir::State::status=/dev/null \
    -o Dir::Cache="$private_apt_dir/cache" \
    -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache= "$@"
}
