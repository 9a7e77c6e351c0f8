# Sourced by the lease scripts on a bare GPU machine: unpacks the debs carried in $DIR (glvnd's
# loaders, fonts), points glvnd at NVIDIA's EGL vendor file, unpacks the portable tarball into
# /tmp and sets TREE to it.
for f in "$DIR"/*.deb; do dpkg -x "$f" /; done
ldconfig
for vendor in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
  if [ -e "$vendor" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor; break; fi
done
tar -C /tmp -xJf "$DIR"/flowsurf-*.tar.xz
TREE=$(ls -d /tmp/flowsurf-*)
