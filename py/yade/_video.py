"""utils.makeVideo: a video from image files (SnapshotEngine's frames), encoded by ffmpeg.

The reference encodes with mencoder in two passes; mencoder is gone from current distributions, so this uses
ffmpeg with the same codec (MPEG-4 part 2) and the same arguments."""
import glob
import os
import shutil
import subprocess
import tempfile
import warnings


def _frames(frameSpec):
    if isinstance(frameSpec, (list, tuple)):
        return [str(f) for f in frameSpec]
    spec = str(frameSpec)
    if '%' in spec:  # a printf-style pattern: the consecutive numbers from 0 (or 1) that exist
        frames, start = [], 0 if os.path.exists(spec % 0) else 1
        while os.path.exists(spec % (start + len(frames))):
            frames.append(spec % (start + len(frames)))
        return frames
    return sorted(glob.glob(spec))


def makeVideo(frameSpec, out, renameNotOverwrite=True, fps=24, kbps=6000, bps=None):
    """Makes a video from image files, as the reference's utils.makeVideo (which uses mencoder; here ffmpeg).

    :param frameSpec: a list or tuple of files, encoded in that order; or a shell wildcard (``/tmp/snap-*.png``,
        sorted by name) or a printf-style pattern (``/tmp/snap-%05d.png``)
    :param str out: the video file (its extension chooses the container: .avi, .mp4, .mkv...)
    :param bool renameNotOverwrite: when `out` exists, write `out` with -1, -2... before its extension instead
    :param int fps: frames per second
    :param int kbps: bit rate in kb/s (bps, in b/s, wins when given)
    :return: the name of the video written
    """
    import sys
    if 'yade.qt' in sys.modules:  # frames a SnapshotEngine took may still be waiting to be saved
        sys.modules['yade.qt']._waitForSnapshots()
    frames = _frames(frameSpec)
    if not frames:
        raise ValueError("makeVideo: no frames match %r" % (frameSpec,))
    missing = [f for f in frames if not os.path.isfile(f)]
    if missing:
        raise ValueError("makeVideo: %d frame(s) do not exist, the first: %s" % (len(missing), missing[0]))
    if not fps > 0:
        raise ValueError("makeVideo: fps must be positive (got %s)" % fps)
    ffmpeg = shutil.which('ffmpeg')
    if ffmpeg is None:
        raise RuntimeError("makeVideo needs ffmpeg (apt-get install ffmpeg)")
    out = str(out)
    if renameNotOverwrite and os.path.exists(out):
        stem, ext = os.path.splitext(out)
        n = 1
        while os.path.exists('%s-%d%s' % (stem, n, ext)):
            n += 1
        out = '%s-%d%s' % (stem, n, ext)
    bitrate = int(bps) if bps else int(kbps) * 1000
    with tempfile.TemporaryDirectory(prefix='yade-video-') as tmp:
        ext = os.path.splitext(frames[0])[1] or '.png'
        for i, f in enumerate(frames):  # numbered links: ffmpeg reads them in this order
            os.symlink(os.path.abspath(f), os.path.join(tmp, '%08d%s' % (i, ext)))
        cmd = [ffmpeg, '-y', '-loglevel', 'error', '-framerate', str(fps), '-i', os.path.join(tmp, '%08d' + ext),
               '-c:v', 'mpeg4', '-b:v', str(bitrate), '-pix_fmt', 'yuv420p',
               '-vf', 'pad=ceil(iw/2)*2:ceil(ih/2)*2', out]
        r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("makeVideo: ffmpeg failed (%s): %s" % (' '.join(cmd), r.stderr.strip()[-2000:]))
    return out


def encodeVideoFromFrames(*args, **kw):
    """Deprecated name of makeVideo (as in the reference)."""
    warnings.warn("encodeVideoFromFrames is deprecated, use makeVideo instead", DeprecationWarning, stacklevel=2)
    return makeVideo(*args, **kw)
