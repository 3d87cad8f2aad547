#!/usr/bin/env python3
"""Two or more shadelgraph binaries (e.g. main's and a branch's) on the same
forward render, alternated run by run, because `shadelgraph bench` alternates
configurations of one binary only.

  tools/alternate_builds.py OLD,NEW MODEL.gltf 1280x720 FRAMES ROUNDS [render options...]

Each round runs every binary once (`render --mode forward --frames FRAMES
--stats`); prints per binary the median and minimum of every frame after the
first (only the last frame for binaries that report one), the median over
rounds of each pass's GPU time and of their sum (the last frame's), and NEW /
OLD of both medians."""
import collections, json, os, statistics, subprocess, sys, tempfile


def main():
    bins = sys.argv[1].split(',')
    model, size, frames, rounds = sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
    extra = sys.argv[6:]
    frame = collections.defaultdict(list)
    passes = collections.defaultdict(lambda: collections.defaultdict(list))
    passSum = collections.defaultdict(list)  # the last frame's GPU pass times, summed
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(rounds):
            for i, b in enumerate(bins):
                stats = os.path.join(tmp, f'stats{i}.json')
                subprocess.run([b, 'render', model, '--mode', 'forward', '--size', size, '--frames', str(frames),
                                '-o', os.path.join(tmp, f'image{i}.png'), '--stats', stats] + extra,
                               check=True, capture_output=True)
                d = json.load(open(stats))
                # Binaries before session 10 report only the last frame (frame_ms).
                frame[i] += d['frames_ms'][1:] or d['frames_ms'] if 'frames_ms' in d else [d['frame_ms']]
                passSum[i].append(sum(d['pass_ms'].values()))
                for k, v in d['pass_ms'].items():
                    passes[i][k].append(v)
    for i, b in enumerate(bins):
        print(b, 'frame median %.1f min %.1f ms (n=%d), passes sum median %.1f ms' %
              (statistics.median(frame[i]), min(frame[i]), len(frame[i]), statistics.median(passSum[i])),
              ' '.join('%s=%.1f' % (k, statistics.median(v)) for k, v in passes[i].items()))
    if len(bins) == 2:
        print('ratio new/old frame median %.3f, passes sum median %.3f' %
              (statistics.median(frame[1]) / statistics.median(frame[0]),
               statistics.median(passSum[1]) / statistics.median(passSum[0])))


if __name__ == '__main__':
    main()
