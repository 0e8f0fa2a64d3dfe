"""Cross-PLC synchronous operation: a follower on a second controller moves in step with a follower on the
first one (S7-1500T V5 §8).  The telegrams travel over an in-process link here; swap in
UadpLeadingValuePublisher / UadpLeadingValueSubscriber for OPC UA PubSub over UDP."""
from plcmotion import Controller
from plcmotion.crossplc import LocalLink
from plcmotion.s7_1500 import MC_GearInPos, MC_MoveVelocity, MC_Power

DELAY = 0.008                                   # set at the leading axis: 2 application cycles of the receiver
link = LocalLink()
a, b = Controller(family="S7-1500T"), Controller(family="S7-1500T")
master = a.add_positioning_axis("Master", {"VirtualAxis": {"Mode": 1}, "CrossPlcSynchronousOperation": {
    "Interface[1]": {"EnableLeadingValueOutput": True}, "LocalLeadingValueDelayTime": DELAY}})
local = a.add_synchronous_axis("Local", {"VirtualAxis": {"Mode": 1}}, leading_values=[("Master", "delayed")])
proxy = b.add_leading_axis_proxy("Proxy", source_link=link)   # the delay comes with the telegrams
remote = b.add_synchronous_axis("Remote", {"VirtualAxis": {"Mode": 1}}, leading_values=["Proxy"])
master.provide_leading_value(link)
pa, pl, pr = MC_Power(), MC_Power(), MC_Power()
move, g_local, g_remote = MC_MoveVelocity(), MC_GearInPos(), MC_GearInPos()
SYNC = dict(RatioNumerator=1, MasterSyncPosition=100.0, SlaveSyncPosition=0.0, MasterStartDistance=50.0)


@a.program
def first():
    pa(Axis=master, Enable=True)
    pl(Axis=local, Enable=True)
    move(Axis=master, Execute=pa.Status, Velocity=200.0)
    g_local(Master=master, Slave=local, Execute=pl.Status, **SYNC)


@b.program
def second():
    pr(Axis=remote, Enable=True)
    g_remote(Master=proxy, Slave=remote, Execute=pr.Status, **SYNC)


for _ in range(500):                            # the sending controller runs first in each cycle
    a.step()
    b.step()
assert g_local.InSync and g_remote.InSync and abs(local.Position - remote.Position) < 1e-9
print(f"master {master.Position:.2f}, local follower {local.Position:.4f}, remote follower {remote.Position:.4f}, "
      f"proxy adjustment time {proxy.StatusExternalLeadingValue.AdjustmentTime * 1000:.1f} ms")
