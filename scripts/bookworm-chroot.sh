# Clean Debian bookworm chroots for the checks that play a new user on a fresh machine
# (scripts/check-fresh-machine.sh, scripts/check-deb-in-chroot.sh). Sourced, not run:
#   source scripts/bookworm-chroot.sh
#   chroot_create DIR             a fresh `debootstrap --variant=minbase bookworm` tree, upgraded
#   chroot_mount DIR [SRC:DEST]   the bind mounts a new user's machine has, and any others
#   chroot_run DIR COMMAND...     runs a command inside, with a minimal environment
#   chroot_unmount DIR            undoes every mount below DIR (chroot_mount arms a trap for it)
#   chroot_remove DIR             unmounts, then deletes the tree
# The archive is the machine's own: the Debian main archive and the updates and security
# suites found in its apt sources, so that the chroot is what a fresh bookworm install
# with those sources gets. Run as root, with debootstrap installed.
#
# Cached in $MOBIUS_CHROOT_CACHE (/var/cache/mobius-chroot), to keep repeated checks quick:
#   base-bookworm.tar   the debootstrap base, upgraded; made again when older than
#                       $MOBIUS_CHROOT_BASE_DAYS (7) days or when the apt sources change
#                       (every chroot is upgraded from the archive when made anyway)
#   apt-archives/       the downloaded .deb files, bind-mounted as /var/cache/apt/archives
#   ccache/             a compiler cache, for the checks that build (mounted by the caller)

chroot_cache="${MOBIUS_CHROOT_CACHE:-/var/cache/mobius-chroot}"
chroot_suite=bookworm

# The machine's apt sources for bookworm's main component, one "URI SUITE" a line: the
# release, its -updates and its -security suites, as found (one-line .list files and
# deb822 .sources files; entries with Enabled: no are skipped). Reads the files given, by
# default the ones apt reads.
chroot_sources() {
  local files=() candidates=("$@")
  if [ $# -eq 0 ]; then
    candidates=(/etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources)
  fi
  for file in "${candidates[@]}"; do
    [ -f "$file" ] && files+=("$file")
  done
  [ ${#files[@]} -gt 0 ] || return 0
  awk -v codename="$chroot_suite" '
    function wanted(suite) { return suite == codename || suite == codename "-updates" ||
                                    suite == codename "-security" }
    function emit(uris, suites, components,   u, s, nu, ns, uri, suite) {
      if (components !~ /(^| )main( |$)/) return
      nu = split(uris, uri, " "); ns = split(suites, suite, " ")
      for (u = 1; u <= nu; u++) for (s = 1; s <= ns; s++)
        if (wanted(suite[s])) print uri[u], suite[s]
    }
    function flush() {
      if (types ~ /(^| )deb( |$)/ && enabled != "no") emit(uris, suites, components)
      types = uris = suites = components = enabled = ""
    }
    FNR == 1 { flush() }
    FILENAME ~ /\.sources$/ {
      if ($0 ~ /^[ \t]*#/) next
      if ($0 ~ /^[ \t]*$/) { flush(); next }
      field = tolower($1); sub(/:$/, "", field); value = $0; sub(/^[^:]*:[ \t]*/, "", value)
      if (field == "types") types = value
      else if (field == "uris") uris = value
      else if (field == "suites") suites = value
      else if (field == "components") components = value
      else if (field == "enabled") enabled = tolower(value)
      next
    }
    {  # one-line format: deb [options] URI SUITE COMPONENT...
      sub(/#.*/, ""); if ($1 != "deb") next
      line = $0; sub(/^[ \t]*deb[ \t]+/, "", line)
      if (line ~ /^\[/) sub(/^\[[^]]*\][ \t]*/, "", line)
      n = split(line, part, /[ \t]+/); rest = ""
      for (i = 3; i <= n; i++) rest = rest " " part[i]
      emit(part[1], part[2], rest)
    }
    END { flush() }
  ' "${files[@]}" | awk '!seen[$0]++'
}

# The archive the base comes from: the URI of the release suite itself.
chroot_mirror() {
  chroot_sources | awk -v codename="$chroot_suite" '$2 == codename { print $1; exit }'
}

# A fresh tree at DIR (which must not exist): the cached base, unpacked and upgraded.
chroot_create() {
  local root="$1"
  if [ -e "$root" ]; then echo "chroot_create: $root exists" >&2; return 1; fi
  chroot_base || return 1
  mkdir -p "$root"
  tar -C "$root" --numeric-owner -xpf "$chroot_cache/base-$chroot_suite.tar" || return 1
  chroot_mount "$root"
  chroot_upgrade "$root"
}

# apt-get update and dist-upgrade in the chroot; their output goes to its
# /var/log/chroot-upgrade.log, shown if they fail.
chroot_upgrade() {
  local root="$1" log="$1/var/log/chroot-upgrade.log"
  { chroot_run "$root" apt-get update -q && chroot_run "$root" apt-get dist-upgrade -y -q; } \
    > "$log" 2>&1 || { tail -20 "$log" >&2; return 1; }
}

# The cached base: debootstrap from the machine's mirror, the machine's bookworm suites in
# its sources.list, upgraded from them (security updates, as an installer applies them).
chroot_base() {
  local tarball="$chroot_cache/base-$chroot_suite.tar" sources mirror key
  sources="$(chroot_sources)"
  mirror="$(chroot_mirror)"
  # What the tarball was made from: a change of the sources or of the recipe remakes it.
  key="$sources"$'\n'"dpkg: force-unsafe-io"
  if [ -z "$mirror" ]; then
    echo "chroot: no '$chroot_suite' suite with component main in /etc/apt/sources.list" \
         "or /etc/apt/sources.list.d: cannot tell which Debian archive to use" >&2
    return 1
  fi
  if [ -f "$tarball" ] && [ "$(cat "$tarball.key" 2> /dev/null)" = "$key" ] &&
     [ -n "$(find "$tarball" -mtime "-${MOBIUS_CHROOT_BASE_DAYS:-7}")" ]; then
    return 0
  fi
  echo "chroot: making the $chroot_suite base from $mirror (cached in $tarball)"
  local work="$chroot_cache/base-work"
  chroot_remove "$work" || return 1
  mkdir -p "$chroot_cache/apt-archives/partial"
  debootstrap --variant=minbase --cache-dir="$chroot_cache/apt-archives" \
    "$chroot_suite" "$work" "$mirror" > "$chroot_cache/debootstrap.log" 2>&1 ||
    { tail -20 "$chroot_cache/debootstrap.log" >&2; return 1; }
  awk '{ print "deb", $1, $2, "main" }' <<< "$sources" > "$work/etc/apt/sources.list"
  # dpkg without a sync per file, as in Debian's container images: the tree is thrown away,
  # and the packages are what they are either way (ParaView's ~700 unpack much faster).
  echo force-unsafe-io > "$work/etc/dpkg/dpkg.cfg.d/unsafe-io"
  (chroot_mount "$work" && chroot_upgrade "$work") || return 1
  rm -rf "$work"/var/lib/apt/lists/* "$work"/tmp/*
  tar -C "$work" --numeric-owner -cpf "$tarball.new" . && mv "$tarball.new" "$tarball" &&
    printf '%s\n' "$key" > "$tarball.key"
  chroot_remove "$work"
}

# Binds /proc, /sys, /dev/shm (pvpython and Xvfb share memory through it) and /dev/pts,
# the apt .deb cache, and every SRC:DEST given (DEST inside the chroot); copies the
# machine's resolv.conf. The mounts are undone when the calling shell exits.
chroot_mount() {
  local root="$1"; shift
  local binds=(/proc:/proc /sys:/sys /dev/shm:/dev/shm /dev/pts:/dev/pts
               "$chroot_cache/apt-archives:/var/cache/apt/archives" "$@")
  mkdir -p "$chroot_cache/apt-archives/partial"
  cp /etc/resolv.conf "$root/etc/resolv.conf"
  for bind in "${binds[@]}"; do
    local source="${bind%%:*}" target="$root${bind#*:}"
    mkdir -p "$source" "$target"
    mountpoint -q "$target" || mount --bind "$source" "$target" || return 1
  done
  # shellcheck disable=SC2064  # the trap must unmount this root, known now
  trap "chroot_unmount '$root'" EXIT
}

# Unmounts everything mounted below DIR, deepest first; fails if anything stays mounted.
chroot_unmount() {
  local root mounts
  root="$(realpath -m "$1")"
  mapfile -t mounts < <(awk -v root="$root/" 'index($2, root) == 1 { print $2 }' /proc/self/mounts | sort -r)
  for mount in "${mounts[@]}"; do
    umount "$mount" 2> /dev/null || umount -l "$mount"
  done
  ! awk -v root="$root/" 'index($2, root) == 1 { found = 1 } END { exit !found }' /proc/self/mounts
}

# Deletes the tree at DIR, only once nothing is mounted in it (a bind mount's files would
# be deleted through it).
chroot_remove() {
  local root="$1"
  [ -e "$root" ] || return 0
  chroot_unmount "$root" || { echo "chroot: something is still mounted in $root" >&2; return 1; }
  rm -rf --one-file-system "$root"
}

# Runs COMMAND in the chroot as root with a minimal environment: no variable of the
# calling shell (PYTHONPATH, LD_LIBRARY_PATH, CCACHE_*, ...) gets in.
chroot_run() {
  local root="$1"; shift
  chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
    DEBIAN_FRONTEND=noninteractive LANG=C.UTF-8 "$@"
}
