import csv, statistics as st
rows = list(csv.DictReader(open('runs.csv')))
for prob in ['DW', 'GE']:
    for pl in ['BITstar', 'RRTConnect']:
        r = [x for x in rows if x['problem'] == prob and x['planner'] == pl]
        ok = [x for x in r if x['exact'] == '1']
        t = [float(x['t_first_ms']) for x in ok]; c = [int(x['calls_first']) for x in ok]
        tt = [float(x['t_total_ms']) for x in r]
        per = [1e6 * float(x['t_first_ms']) / int(x['calls_first']) for x in ok]
        mt, mc = st.median(t), st.median(c)
        print(f"{prob} {pl:10s} success {len(ok)}/{len(r)}  median t_first {mt:7.2f} ms (min {min(t):.2f}, max {max(t):.2f})"
              f"  median calls_first {mc:9.0f}  median/median {1e6*mt/mc:5.1f} ns/call  median of per-run ns/call {st.median(per):5.1f}"
              f"  median t_total {st.median(tt):7.2f} ms  median cost {st.median(float(x['cost']) for x in ok):.4f}"
              f"  callbacks {sum(x['callback']=='1' for x in r)}  median setup {st.median(float(x['setup_ms']) for x in r):.3f} ms")
