#!/usr/bin/env python3
"""Leave-one-performer-out evaluation of `kumite suggest` over every annotated capture folder.

Ground truth: data/annotations/reference.json (hand-checked strikes and blocks) and data/evaluation/*-moves.json
(moves listed in a folder's SOURCE.md). Every capture of the folders below is run, those with no strike included
(walks, dances, ducks, hit reactions): a strike proposed there counts against precision.

Protocol: each threshold set of the grid (--grid, `kumite suggest --thresholds`) is run once over every capture.
For each performer held out, the set with the best score on the *other* performers is chosen and scored on the held
out one; the table shows those held-out figures. With no grid, the built-in thresholds are scored as they are.

Scores per performer (hits matched one to one, same semantics and side, within 0.25 s, nearest first):
- strikes (punch, kick, knee, elbow): recall and precision; a proposal at an annotated slash (an empty-hand sword
  swing, a semantics suggest does not propose) counts neither way;
- blocks as strikes: block moves with any strike proposed within 0.25 s of them (a one-technique block capture is
  one move and counts if any strike is proposed in it), over all block moves;
- block recall: annotated blocks matched by a proposed block (a two-handed cover matches either arm);
- block precision: proposed blocks that match one (a two-handed cover is a block of each arm), in the captures whose
  blocks are all annotated (not the kata's).
Strikes proposed in captures nobody annotated (walks, dances: not fights) are counted apart, per performer.

  python3 scripts/suggest_lopo.py [--kumite build/bin/kumite] [--grid scripts/suggest_lopo_grid.json] [--json OUT]
"""
import argparse
import collections
import concurrent.futures
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FOLDERS = ['bandai-namco-1', 'cmu-hahne-mb', 'cmu-iclone-cc4', 'cmu14-boxing', 'hachaj-shorinryu', 'hachaj-kata', 'snu-boxing']
STRIKES = {'punch', 'kick', 'knee', 'elbow'}
TOLERANCE_S = 0.25


def performer_of(source):
    folder, name = source.split('/', 1)
    if folder == 'bandai-namco-1':
        return 'bandai'
    if folder in ('cmu-hahne-mb', 'cmu-iclone-cc4'):
        # The same CMU subjects in two exports: subject 02 throws the strikes, the others (walks, dances) none.
        subject = name.split('_')[0].lstrip('0')
        return 'cmu02' if subject == '2' else 'cmu-other'
    if folder == 'cmu14-boxing':
        return 'cmu14'
    if folder == 'hachaj-shorinryu':
        return 'shorinryu'
    if folder == 'hachaj-kata':
        return 'kata-danuta' if name[0].isdigit() else 'kata-marcin'  # SOURCE.md: number prefix = Danuta
    if folder == 'snu-boxing':
        return 'snu'
    return folder


def load_ground_truth(mocap):
    """source -> list of moves {semantics, side, hit_frame}; source -> fps given by the annotation file."""
    moves = collections.defaultdict(list)
    reference = json.load(open(os.path.join(ROOT, 'data/annotations/reference.json')))
    fps = {source: value['fps'] for source, value in reference.get('captures', {}).items()}
    for clip in reference['clips']:
        if 'hit_frame' not in clip:
            continue  # rest and steps
        moves[clip['source']].append({'semantics': clip['semantics'], 'side': clip['side'], 'hit_frame': clip['hit_frame']})
    evaluation = os.path.join(ROOT, 'data/evaluation')
    for name in sorted(os.listdir(evaluation)):
        if name.endswith('-moves.json'):
            listed = json.load(open(os.path.join(evaluation, name)))
            for move in listed['moves']:
                moves[move['source']].append(move)
            for source in listed.get('captures_without_moves', []):
                moves.setdefault(source, [])
    # Captures with annotations (strikes, blocks, rest or steps) or listed as holding no move are scored; the other
    # captures of the folders (walks, dances, bows, ball games: nobody annotated them) are not fights.
    for clip in reference['clips']:
        moves.setdefault(clip['source'], [])
    captures = []
    for folder in FOLDERS:
        path = os.path.join(mocap, folder)
        if not os.path.isdir(path):
            sys.exit(f'suggest_lopo: {path} is missing (run scripts/fetch_mocap.sh)')
        captures += sorted(f'{folder}/{name}' for name in os.listdir(path) if name.endswith('.bvh'))
    return captures, moves, fps


def run_suggest(kumite, mocap, sources, fps, thresholds):
    """source -> proposed strikes, one `suggest --json` per frame rate group."""
    groups = collections.defaultdict(list)
    for source in sources:
        groups[fps.get(source)].append(source)
    proposed = {}
    for rate, members in groups.items():
        for start in range(0, len(members), 60):
            chunk = members[start:start + 60]
            command = [kumite, 'suggest', '--json', '--mocap-root', mocap] + [os.path.join(mocap, s) for s in chunk]
            if rate:
                command += ['--fps', str(rate)]
            if thresholds:
                command += ['--thresholds', ','.join(f'{k}={v}' for k, v in sorted(thresholds.items()))]
            done = subprocess.run(command, capture_output=True, text=True)
            if done.returncode != 0:
                sys.exit(f'suggest_lopo: {" ".join(command[:4])} ... failed: {done.stderr.strip()[-400:]}')
            report = json.loads(done.stdout)
            files = report['files'] if 'files' in report else [{'file': command[5], 'strikes': report['strikes']}]
            for source, entry in zip(chunk, files):
                proposed[source] = entry['strikes']
    return proposed


def match(moves, proposals, tolerance, fits):
    """One-to-one pairs (move index, proposal index) with fits(move, proposal) and hits within tolerance, nearest first."""
    pairs = sorted((abs(m['hit_frame'] - p['hit_frame']), i, j) for i, m in enumerate(moves) for j, p in enumerate(proposals)
                   if fits(m, p) and abs(m['hit_frame'] - p['hit_frame']) <= tolerance)
    used_m, used_p, matched = set(), set(), []
    for _, i, j in pairs:
        if i in used_m or j in used_p:
            continue
        used_m.add(i)
        used_p.add(j)
        matched.append((i, j))
    return matched


def score_capture(source, moves, proposals, frame_rate):
    """Counts of one capture: strikes annotated/proposed/matched, block moves, blocks taken for strikes, blocks found."""
    tolerance = max(1, round(TOLERANCE_S * frame_rate))
    strike_moves = [m for m in moves if m['semantics'] in STRIKES]
    block_moves = [m for m in moves if m['semantics'] == 'block']
    slashes = [m for m in moves if m['semantics'] == 'slash']
    strikes = [p for p in proposals if p['semantics'] in STRIKES]
    blocks = [p for p in proposals if p['semantics'] == 'block']
    same = lambda m, p: m['semantics'] == p['semantics'] and m['side'] == p['side']
    matched = match(strike_moves, strikes, tolerance, same)
    matched_p = {j for _, j in matched}
    neutral = sum(1 for j, p in enumerate(strikes) if j not in matched_p and
                  any(abs(s['hit_frame'] - p['hit_frame']) <= tolerance for s in slashes))
    # A two-handed cover is a block of each arm: either arm proposed finds it, and both arms proposed are both right.
    arm_moves = [(index, side) for index, m in enumerate(block_moves) for side in (('left', 'right') if m['side'] == 'both' else (m['side'],))]
    arm_pairs = match([dict(block_moves[index], side=side) for index, side in arm_moves], blocks, tolerance,
                      lambda m, p: m['side'] == p['side'])
    blocks_found = len({arm_moves[i][0] for i, _ in arm_pairs})
    blocks_right = len(arm_pairs)
    one_technique = source.startswith('hachaj-shorinryu/')
    if one_technique:
        taken = int(bool(block_moves) and bool(strikes))
    else:
        taken = sum(1 for m in block_moves if any(abs(m['hit_frame'] - p['hit_frame']) <= tolerance for p in strikes))
    # Block precision only where every block is annotated: the kata's blocks are only partly.
    blocks_known = not source.startswith('hachaj-kata/')
    return collections.Counter(annotated=len(strike_moves), proposed=len(strikes) - neutral, matched=len(matched),
                               block_moves=len(block_moves), blocks_as_strikes=taken, blocks_found=blocks_found,
                               blocks_proposed_known=len(blocks) if blocks_known else 0,
                               blocks_found_known=blocks_right if blocks_known else 0)


def frame_rates(mocap, sources, fps):
    """source -> frames per second: the annotation file's for captures that give none, else the file's Frame Time."""
    rates = {}
    for source in sources:
        if source in fps:
            rates[source] = fps[source]
            continue
        with open(os.path.join(mocap, source), errors='replace') as f:
            for line in f:
                if line.strip().lower().startswith('frame time'):
                    rates[source] = 1.0 / float(line.split(':')[1])
                    break
    return rates


def frames_in(path):
    with open(path, errors='replace') as f:
        for line in f:
            if line.strip().lower().startswith('frames:'):
                return int(line.split(':')[1])
    return 0


def tally(per_capture, sources):
    total = collections.Counter()
    for source in sources:
        total.update(per_capture[source])
    return total


def figures(total):
    ratio = lambda a, b: a / b if b else None
    return {'strikes': total['annotated'], 'recall': ratio(total['matched'], total['annotated']),
            'precision': ratio(total['matched'], total['proposed']), 'proposed': total['proposed'],
            'block_moves': total['block_moves'], 'blocks_as_strikes': ratio(total['blocks_as_strikes'], total['block_moves']),
            'block_recall': ratio(total['blocks_found'], total['block_moves']),
            'block_precision': ratio(total['blocks_found_known'], total['blocks_proposed_known'])}


def objective(f):
    """How a threshold set does on one performer: its worst bar, each relative to the issue's bar (1 = met)."""
    terms = []
    if f['recall'] is not None:
        terms.append(f['recall'] / 0.9)
    if f['precision'] is not None:
        terms.append(f['precision'] / 0.9)
    if f['blocks_as_strikes'] is not None:
        terms.append((1.0 - f['blocks_as_strikes']) / 0.95)
    if f['block_recall'] is not None:
        terms.append(f['block_recall'] / 0.8)
    return min(terms) if terms else 0.0


def percent(value):
    return '   -' if value is None else f'{100 * value:4.0f}'


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--kumite', default=os.path.join(ROOT, 'build/bin/kumite'))
    parser.add_argument('--mocap', default=os.path.join(ROOT, 'data/mocap'))
    parser.add_argument('--grid', help='JSON list of threshold sets ({name: value}) to choose from per held-out performer')
    parser.add_argument('--json', help='write the table and every capture\'s misses and extras here')
    parser.add_argument('--details', action='store_true', help='print each capture\'s missed and extra strikes')
    args = parser.parse_args()
    mocap = os.path.realpath(args.mocap)
    captures, moves, fps = load_ground_truth(mocap)
    rates = frame_rates(mocap, captures, fps)
    grid = json.load(open(args.grid)) if args.grid else [{}]

    def run(thresholds):
        proposed = run_suggest(args.kumite, mocap, captures, fps, thresholds)
        return proposed, {s: score_capture(s, moves.get(s, []), proposed[s], rates[s]) for s in captures}

    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        runs = list(pool.map(run, grid))
    scored = [s for s in captures if s in moves]
    unannotated = [s for s in captures if s not in moves]
    performers = collections.defaultdict(list)
    for source in scored:
        performers[performer_of(source)].append(source)
    rows, chosen = {}, {}
    for performer, held_out in sorted(performers.items()):
        # Chosen on the others: the mean over the training performers of each one's worst bar (capped at met), so
        # that a set is worth most when it meets the bars on the most performers.
        others = [p for p in performers if p != performer]
        scores = [sum(min(1.0, objective(figures(tally(per_capture, performers[p])))) for p in others) / len(others)
                  for _, per_capture in runs]
        best = max(range(len(runs)), key=lambda i: (round(scores[i], 9), -i))  # ties: the earlier set (the grid's order)
        chosen[performer] = best
        rows[performer] = figures(tally(runs[best][1], held_out))
    everyone = figures(tally(runs[0][1], scored)) if len(runs) == 1 else None
    # Strikes proposed in the captures nobody annotated (not fights: any strike there is a false one), per performer.
    false_elsewhere = collections.Counter()
    minutes = collections.Counter()
    for source in unannotated:
        chosen_run = runs[chosen.get(performer_of(source), 0)]
        false_elsewhere[performer_of(source)] += sum(1 for p in chosen_run[0][source] if p['semantics'] in STRIKES)
        minutes[performer_of(source)] += frames_in(os.path.join(mocap, source)) / rates[source] / 60.0

    print(f'{"held-out performer":<18} {"strikes":>7} {"recall%":>7} {"precision%":>10} {"block moves":>11} '
          f'{"blocks as strikes%":>18} {"block recall%":>13} {"block precision%":>16}  threshold set')
    for performer, f in rows.items():
        print(f'{performer:<18} {f["strikes"]:>7} {percent(f["recall"]):>7} {percent(f["precision"]):>10} {f["block_moves"]:>11} '
              f'{percent(f["blocks_as_strikes"]):>18} {percent(f["block_recall"]):>13} {percent(f["block_precision"]):>16}  {chosen[performer]}')
    if everyone:
        f = everyone
        print(f'{"(all)":<18} {f["strikes"]:>7} {percent(f["recall"]):>7} {percent(f["precision"]):>10} {f["block_moves"]:>11} '
              f'{percent(f["blocks_as_strikes"]):>18} {percent(f["block_recall"]):>13} {percent(f["block_precision"]):>16}')
    for performer in sorted(minutes):
        print(f'not fights, {performer}: {false_elsewhere[performer]} strikes proposed in '
              f'{sum(1 for s in unannotated if performer_of(s) == performer)} captures ({minutes[performer]:.1f} min)')
    if len(grid) > 1:
        for i, thresholds in enumerate(grid):
            print(f'  set {i}: {thresholds or "built-in"}')
    details = {}
    for source in scored:
        per = runs[chosen[performer_of(source)]][1][source]
        mine = moves.get(source, [])
        got = runs[chosen[performer_of(source)]][0][source]
        if per['annotated'] != per['matched'] or per['proposed'] != per['matched'] or per['blocks_as_strikes'] or \
                per['block_moves'] != per['blocks_found']:
            details[source] = {'moves': [(m['semantics'], m['side'], m['hit_frame']) for m in mine],
                               'proposed': [(p['semantics'], p['side'], p['hit_frame']) for p in got]}
            if args.details:
                print(f'{source}: annotated {per["annotated"]} proposed {per["proposed"]} matched {per["matched"]}; '
                      f'blocks {per["block_moves"]} found {per["blocks_found"]} as strikes {per["blocks_as_strikes"]}')
                print('   moves   ', sorted(details[source]['moves'], key=lambda m: m[2]))
                print('   proposed', details[source]['proposed'])
    if args.json:
        json.dump({'held_out': rows, 'chosen': {p: grid[i] for p, i in chosen.items()}, 'captures': details,
                   'not_fights': {p: {'strikes': false_elsewhere[p], 'minutes': minutes[p]} for p in minutes}},
                  open(args.json, 'w'), indent=1)


if __name__ == '__main__':
    main()
