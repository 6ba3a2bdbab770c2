"""Verdicts on the thesis's claims: holds, partly or does not hold, from the numbers claims.py measures.

The thesis states most claims as facts ("the map is correct", "no drift", "Rule 29 returns to the old
RltXPoint") or as times on its 2004 Athlon 64 3400+. Each function here takes the numbers a claim's
run gave (plain numbers and dicts: pure, no files) and returns (verdict, parts): the parts are the
claim's pieces, each (what was checked, with the number, True when it held). A claim holds when every
part held, partly when some did, and does not hold when none did, unless the function says otherwise.
The thresholds are our reading of the thesis's words; each is named and tagged [C].
"""
import math

HOLDS, PARTLY, DOES_NOT = "holds", "partly", "does not hold"

# Times: the thesis's 2004 processor is no yardstick for today's milliseconds, but a time it reports is
# a budget its algorithm met. Ours holds at or under the thesis's, partly up to TIME_PARTLY times it [C].
TIME_PARTLY = 2.0
# "About" a number or a ratio: within a factor ABOUT of it [C].
ABOUT = 2.0
# A change counts (better, worse, fewer) when it is at least CHANGE of the other value [C].
CHANGE = 0.10
# Noise-free identity (E31) and noise-free exactness (E21): differences up to EXACT units are rounding [C].
EXACT = 1e-6


def of_parts(parts):
    """HOLDS when every part held, PARTLY when some did, DOES_NOT when none did (or there are none)."""
    held = sum(bool(ok) for _, ok in parts)
    return HOLDS if parts and held == len(parts) else PARTLY if held else DOES_NOT


def judged(parts):
    """(verdict, parts) by of_parts."""
    return of_parts(parts), parts


def text(verdict_parts):
    """'part: yes; part: no' for the claim's table."""
    return "; ".join(f"{what}: {'yes' if ok else 'no'}" for what, ok in verdict_parts[1])


def within_time(ours_ms, thesis_ms, what="time"):
    """A time the thesis reports: ours at or under it holds, up to TIME_PARTLY times it partly."""
    part = f"{what} {ours_ms:.3g} ms at most the thesis's {thesis_ms:.3g} ms"
    if not math.isfinite(ours_ms):
        return DOES_NOT, [(part, False)]
    verdict = HOLDS if ours_ms <= thesis_ms else PARTLY if ours_ms <= TIME_PARTLY * thesis_ms else DOES_NOT
    return verdict, [(part, verdict == HOLDS)]


def within_share(ours_pct, thesis_pct, what="share"):
    """A share the thesis bounds ("< 2 %"): at or under it holds, up to TIME_PARTLY times it partly."""
    part = f"{what} {ours_pct:.2g} % under the thesis's {thesis_pct:g} %"
    verdict = HOLDS if ours_pct <= thesis_pct else PARTLY if ours_pct <= TIME_PARTLY * thesis_pct else DOES_NOT
    return verdict, [(part, verdict == HOLDS)]


def same_ratio(ours_a, ours_b, thesis_a, thesis_b, what="a/b"):
    """Two times the thesis sets against each other (octree vs quadtree): our ratio on the same side of 1
    as the thesis's and within a factor ABOUT of it holds; on the same side but further, partly; on the
    other side, does not hold."""
    ours, thesis = (ours_a / ours_b if ours_b else float("nan")), thesis_a / thesis_b
    if not math.isfinite(ours) or ours <= 0:
        return DOES_NOT, [(f"{what}: no ratio ({ours_a:.3g} / {ours_b:.3g})", False)]
    same_side = (ours > 1) == (thesis > 1) and ours != 1
    close = same_side and max(ours / thesis, thesis / ours) <= ABOUT
    parts = [(f"{what} {ours:.2f} on the thesis's side of 1 ({thesis:.2f})", same_side),
             (f"within a factor {ABOUT:g} of it", close)]
    return (HOLDS if close else PARTLY if same_side else DOES_NOT), parts


INVARIANT = 0.1  # [C] "constant up to noise": a tenth of the raw spread at most


def rule3_invariance(raw_std, rule3_std, rule3_mean, true):
    """E01 (Fig 66): the raw midpoint difference varies with the heading, the Rule 3 offset does not. Holds
    when Rule 3's spread is under INVARIANT of the raw spread on both axes and its mean is the true offset
    within three of its spreads."""
    spread = max(rule3_std)
    off = max(abs(m - t) for m, t in zip(rule3_mean, true))
    return judged([(f"Rule 3 spread {spread:.3g} under {INVARIANT:g} of the raw spread {min(raw_std):.3g}",
                    spread <= INVARIANT * min(raw_std)),
                   (f"Rule 3 mean {off:.2g} off the true offset, within 3 spreads", off <= 3 * spread)])


def completed_map(walls_mapped, walls_seen, max_position_error, key_point_share):
    """E21 noise-free: every wall seen is mapped, the pose exact, every key point right."""
    return judged([(f"{walls_mapped:.0f} of {walls_seen:.0f} walls mapped", walls_mapped == walls_seen),
                   (f"pose exact (max error {max_position_error:.2g})", max_position_error <= EXACT),
                   (f"key points right {100 * key_point_share:.2f} %", key_point_share >= 0.99)])


ON_LINE, ON_LINE_DEG = 0.1, 1.0  # [C] a plane "on its wall": within 0.1 units and 1° of the wall's line
ENDS = 0.1  # [C] ends right: the walls' mean end error under ten times the plane noise σ_p = 0.01


def plane_map(walls_mapped, walls_seen, pose_valid, errors):
    """A Chapter 5 map the thesis judged by eye (Figs 105-108, paper Figs 7/8): every wall seen mapped with
    the pose valid in 90 % of iterations, every plane on its wall's line, the ends right. errors:
    planes.plane_map_errors (off the line, angle, mean end error)."""
    off, angle, ends = errors
    return judged([(f"{walls_mapped:.0f} of {walls_seen:.0f} walls mapped, pose valid {100 * pose_valid:.0f} %",
                    walls_mapped == walls_seen and pose_valid >= 0.9),
                   (f"every plane on its wall's line (off by {off:.2g}, {angle:.2g}°)",
                    off <= ON_LINE and angle <= ON_LINE_DEG),
                   (f"ends right (mean end error {ends:.3g})", ends < ENDS)])


def rule21_groups(off, uncapped, capped):
    """E10 (Fig 82): Rule 21 makes more groups (21 → 30 in the thesis) and the cap fewer than uncapped."""
    return judged([(f"more groups with Rule 21 ({uncapped} vs {off})", uncapped > off),
                   (f"the cap reduces the count ({capped} vs {uncapped})", capped < uncapped)])


def identical(largest_difference, bound=1e-9):
    """E31: the same map whatever the chain order, plane by plane within `bound`."""
    return judged([(f"largest difference {largest_difference:.2g} within {bound:g}", largest_difference <= bound)])


def em_bench(scores, failures, defaults):
    """E30 (Figs 56-61): each failure case shows its failure (some extractor's recall or precision under
    1) and the defaults avoid them (every extractor 1 and 1). scores: {case: {extractor: (recall,
    precision)}}; failures, defaults: case names."""
    def perfect(case):
        return all(r >= 1 and p >= 1 for r, p in scores[case].values())
    parts = [(f"{case} fails", not perfect(case)) for case in failures]
    parts += [(f"{case} perfect", perfect(case)) for case in defaults]
    return judged(parts)


TWICE = 1.6  # [C] "about twice as fast": EM1/EM2 at least this (2 within a factor 1.25)
SIMILAR = 0.02  # [C] "similar quality": recall and precision within this of each other


def em2_speed(ratios, quality_gaps):
    """E29: EM2 about twice as fast as EM1 on every map (EM1/EM2 ≥ TWICE), similar quality. Speed is the
    claim: faster on every map but less than TWICE is partly, slower anywhere does not hold."""
    fast = all(r >= TWICE for r in ratios)
    faster = all(r > 1 for r in ratios)
    similar = all(g <= SIMILAR for g in quality_gaps)
    parts = [(f"EM1/EM2 {', '.join(f'{r:.2f}' for r in ratios)} at least {TWICE:g}", fast),
             (f"recall and precision within {SIMILAR:g}", similar)]
    return (HOLDS if fast and similar else PARTLY if faster else DOES_NOT), parts


def moving_average_window(noise_free, noisy, default):
    """E23 (thesis 5.2): another window w_ma fixes the noise-free turn error (final mean map error lower
    by CHANGE) and the windows other than the default harm the noisy map (an error higher by CHANGE or
    fewer walls). noise_free, noisy: {window: (final mean map error, walls mapped)}."""
    base, nbase = noise_free[default], noisy[default]
    fixes = [w for w, (e, _) in noise_free.items() if w != default and e <= (1 - CHANGE) * base[0]]
    harms = [w for w, (e, n) in noisy.items() if w != default and (e >= (1 + CHANGE) * nbase[0] or n < nbase[1])]
    return judged([(f"another window lowers the noise-free error {base[0]:.3g} ({', '.join(fixes) or 'none'})",
                    bool(fixes)),
                   (f"another window harms the noisy map ({', '.join(harms) or 'none'})", bool(harms))])


DEGRADES = 1.25  # [C] the map degrades: the noisiest run's map error at least this times the noise-free one's


def noise_sweep(first_error, last_error, lowest_recall, trouble):
    """E28 (paper §III): the map degrades as the noise rises; past some level EM has trouble finding
    planes (its frame-mean recall under `trouble`)."""
    return judged([(f"map error {first_error:.3g} → {last_error:.3g}", last_error >= DEGRADES * first_error),
                   (f"EM's recall under {trouble:g} at some noise (lowest {lowest_recall:.3g})",
                    lowest_recall < trouble)])


APART = 3.0  # [C] E02: the other pairs' σ at least this times the chosen pair's


def key_point_pair(chosen_sigma, other_sigmas, real_end_shares):
    """E02 (Fig 68): the pair of the two static ends has the lowest σ, clearly (the others APART times
    higher), and its key points are the real ends (in 95 % of iterations or more)."""
    return judged([(f"σ {chosen_sigma:.3g}, the others at least {APART:g}× it",
                     min(other_sigmas) >= APART * chosen_sigma),
                   ("its ends are real wall ends", min(real_end_shares) >= 0.95)])


def interval_mode(group_gaussian, pair_gaussian, group_three, pair_three):
    """E07 (Figs 74/75): pair intervals noisier than group intervals under random noise (pair's map error
    higher by CHANGE); with three-valued rotation noise the difference goes. Without the first there is
    nothing to go: does not hold."""
    noisier = pair_gaussian >= (1 + CHANGE) * group_gaussian
    gone = pair_three < (1 + CHANGE) * group_three
    parts = [(f"pair noisier than group under random noise ({pair_gaussian:.3g} vs {group_gaussian:.3g})", noisier),
             (f"not under three-valued noise ({pair_three:.3g} vs {group_three:.3g})", gone)]
    return (of_parts(parts) if noisier else DOES_NOT), parts


def wrong_key_points_heal(longest_episode, never_healed, heal_iterations):
    """E08 (Figs 76-79): a wrong key point corrects itself within heal_iterations; no lasting map error."""
    return judged([(f"longest wrong key-point episode {longest_episode} iterations, at most {heal_iterations}",
                    longest_episode <= heal_iterations),
                   (f"{never_healed} map-error events never healed", never_healed == 0)])


def rule21_full_size(off_under_sized, on_under_sized):
    """E09 (Figs 80/81): Rule 21 off leaves a wall under-sized; every variant with it, none."""
    return judged([(f"off: {off_under_sized} wall(s) under-sized", off_under_sized > 0),
                   (f"on: {sum(on_under_sized)} under-sized", sum(on_under_sized) == 0)])


def rule22_saving(on_ms, off_ms, thesis_share=0.05):
    """E10 (thesis 4.3.5): Rule 22 saves about 5 % of the time while revisiting (within a factor ABOUT)."""
    saving = 1 - on_ms / off_ms if off_ms > 0 else float("nan")
    saves = saving > 0
    about = saves and max(saving / thesis_share, thesis_share / saving) <= ABOUT
    parts = [(f"saves {100 * saving:.1f} %", saves), (f"about the thesis's {100 * thesis_share:g} %", about)]
    return of_parts(parts), parts


def rule28(on_misplaced, off_misplaced):
    """E12 (Fig 87): without Rule 28 a plane ends off its wall's line; with it none does."""
    return judged([(f"off: {off_misplaced} plane(s) off their line", off_misplaced > 0),
                   (f"on: {on_misplaced}", on_misplaced == 0)])


def map_e_loop_closure(all_on, resize_off, rule19_off):
    """E15 (Figs 90-92): with every rule a duplicate is kept; without the first-reading resize, and without
    Rule 19, a worse map (more duplicates, or a map error higher by CHANGE). Each: (duplicates, error)."""
    def worse(v):
        return v[0] > all_on[0] or v[1] >= (1 + CHANGE) * all_on[1]
    return judged([(f"a duplicate kept ({all_on[0]:.0f})", all_on[0] >= 1),
                   (f"resize off worse ({resize_off[0]:.0f} duplicates, error {resize_off[1]:.3g} vs "
                    f"{all_on[1]:.3g})", worse(resize_off)),
                   (f"Rule 19 off worse (error {rule19_off[1]:.3g})", worse(rule19_off))])


def collinear(ties, walls_mapped, walls_seen, map_error, correct_map):
    """E18 (Fig 97): the collinear pieces tie (the thesis's trap is there), and with the distance test the
    map is correct. The misplacement without the test is not run: only the fix is judged."""
    return judged([(f"{ties} ties", ties > 0),
                   (f"with the distance test {walls_mapped:.0f} of {walls_seen:.0f} walls, error {map_error:.3g} "
                    f"under {correct_map:g}", walls_mapped == walls_seen and map_error < correct_map)])


def save_system(walls):
    """E19 (Figs 98-100): save_off loses walls; save_on, either rule alone and the big store keep them
    all. walls: {variant: (mapped, seen)}."""
    lost = walls["save_off"][0] < walls["save_off"][1]
    kept = [v for v in walls if v != "save_off" and walls[v][0] == walls[v][1]]
    return judged([(f"without the save system {walls['save_off'][0]:.0f} of {walls['save_off'][1]:.0f}", lost),
                   (f"every wall kept by {', '.join(kept) or 'none'} ({len(kept)} of {len(walls) - 1})",
                    len(kept) == len(walls) - 1)])


def pseudo_merge(differ, plane1_on, plane1_off, correct_map):
    """E20 (Figs 101/102), per seed: Rule 37 changes the current group, and without it plane 1 is
    mis-mapped (e_ends over correct_map and higher by CHANGE than with it). differ: iterations with
    another current group per seed; plane1_*: plane 1's e_ends per seed (NaN: not mapped)."""
    def mismapped(on, off):
        return not math.isfinite(off) or (off > correct_map and off >= (1 + CHANGE) * on)
    bad = sum(mismapped(a, b) for a, b in zip(plane1_on, plane1_off))
    return judged([(f"another current group in {', '.join(map(str, differ))} iterations", all(d > 0 for d in differ)),
                   (f"plane 1 mis-mapped without Rule 37 in {bad} of {len(plane1_off)} seeds", bad > 0)])


FLAT = 1.5  # [C] time per iteration "flat": the longer run's at most this times the shorter's


def flat_time(shortest, longest):
    """E32 (4.2.2, 4.3.8): the time per iteration follows the planes in view, not the map size: the
    longest run's median, and its last tenth (the same stretch of path as the shortest run's last tenth,
    with a bigger map), at most FLAT times the shortest run's. Each: (median, last tenth)."""
    median, end = longest[0] / shortest[0], longest[1] / shortest[1]
    return judged([(f"median {median:.2f}× the shortest run's", median <= FLAT),
                   (f"last tenth {end:.2f}× the shortest run's", end <= FLAT)])


HALLWAY_END = 5.0  # [C] units: the motion model "starts at the end of the hallway"


def first_corner(starts_before, grown, wrong_claims, longest_wrong, heal_iterations):
    """E11 (Figs 83-86): the motion model starts at the end of the hallway (within HALLWAY_END units of the
    turn), the end wall grows during the turn (tracked to 0.95 of its length or more), and a short
    key-point failure occurs and heals (wrong claims, none longer than heal_iterations)."""
    return judged([(f"starts {max(starts_before):.2g} units before the turn", max(starts_before) <= HALLWAY_END),
                   (f"end wall tracked to {min(grown):.3f} of its length", min(grown) >= 0.95),
                   (f"a brief key-point failure ({wrong_claims} wrong claims, longest {longest_wrong})",
                    wrong_claims > 0 and longest_wrong <= heal_iterations)])


A_LITTLE = 1.05  # [C] "a little past its true size": at most 5 % longer


def grown_past(ratios):
    """E13 (Fig 88): with noise some plane is grown past its true size (by 0.1 % or more), a little."""
    past = sum(r > 1.001 for r in ratios)
    return judged([(f"{past} of {len(ratios)} past the true size", past > 0),
                   (f"at most {max(ratios):.3f}, under {A_LITTLE:g}", max(ratios) <= A_LITTLE)])


def frustum(small_max_seen, small_end_seen, small_mapped, large_mapped, true_length):
    """E14 (Fig 89): with the small planar frustum the end wall grows then shrinks in view (its longest
    view beyond its last by CHANGE) and is mapped longer than it is ever seen; the large frustum maps it
    at its true length (within 5 %)."""
    return judged([(f"in view up to {small_max_seen:.3g}, {small_end_seen:.3g} at the turn's end",
                    small_max_seen >= (1 + CHANGE) * small_end_seen),
                   (f"mapped {small_mapped:.3g}, longer than seen", small_mapped >= (1 + CHANGE) * small_max_seen),
                   (f"large frustum maps {large_mapped:.3g} of {true_length:.3g}",
                    abs(large_mapped - true_length) <= 0.05 * true_length)])


def rule29(on_back, off_back, on_groups, off_groups):
    """E16 (Fig 93): with Rule 29 motion models end in groups made before them, without it none do, and
    fewer groups are made with it."""
    return judged([(f"on: {on_back} end in an older group", on_back > 0), (f"off: {off_back}", off_back == 0),
                   (f"groups {on_groups} on vs {off_groups} off", on_groups < off_groups)])


def interval_checks(off, on):
    """E17 (Figs 94-96): without the checks a plane is barely mapped (a wall lost, or a map error higher by
    CHANGE than with them); with them roll-backs happen and every wall is mapped. Each: (walls mapped,
    walls seen, final mean map error, roll-backs)."""
    return judged([(f"off: {off[0]:.0f} of {off[1]:.0f} walls, error {off[2]:.3g} vs {on[2]:.3g}",
                    off[0] < off[1] or off[2] >= (1 + CHANGE) * on[2]),
                   (f"on: {on[3]:.0f} roll-backs, {on[0]:.0f} of {on[1]:.0f} walls", on[3] > 0 and on[0] == on[1])])


def one_partial_plane(single, active):
    """E22 (Fig 69): where one partial plane is in view the motion model is active: in 90 % of those
    iterations holds, half partly."""
    share = active / single if single else 0.0
    verdict = HOLDS if share >= 0.9 else PARTLY if share >= 0.5 else DOES_NOT
    return verdict, [(f"motion model active in {100 * share:.0f} % of {single} single-plane iterations",
                      verdict == HOLDS)]
