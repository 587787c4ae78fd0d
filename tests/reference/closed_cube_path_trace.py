"""Reference radiosity for the floor-lit closed unit cube (tests/test_progressive.cpp), by an
independent path tracer: the floor emits E = 1, every face reflects rho = 0.5. For each face it
averages B = E + rho * H over uniformly sampled points, H from cosine-sampled paths of up to 40
bounces (rho^40 is negligible). Needs numpy; not part of the build.

    python3 tests/reference/closed_cube_path_trace.py

Printed with seed 1 and 2,000,000 paths per face (mean, standard error):
    floor   1.104305  7.9e-05
    ceiling 0.171168  1.5e-04
    side    0.181213  1.5e-04
These differ from the one-patch-per-face solution (1.09091, 0.181746, 0.181836) because the
radiosity is not uniform over a face: the walls are brighter near the lit floor.
"""
import numpy as np
rng=np.random.default_rng(1)
# faces: (axis, level, inward normal sign); floor = (1,0,+1) emits E=1 (L=1/pi)
rho=0.5
def trace(o,d):
    # inside unit cube: exit t per axis
    t=np.where(d>0,(1-o)/d,np.where(d<0,(0-o)/d,np.inf))
    ax=np.argmin(t,axis=1); tm=t[np.arange(len(o)),ax]
    p=o+d*tm[:,None]
    lvl=(d[np.arange(len(o)),ax]>0).astype(float)
    return p,ax,lvl
def cosdir(n_axis,sign,m):
    u1,u2=rng.random(m),rng.random(m)
    r=np.sqrt(u1);phi=2*np.pi*u2
    x=r*np.cos(phi);y=r*np.sin(phi);z=np.sqrt(1-u1)
    d=np.zeros((m,3))
    a1=(n_axis+1)%3;a2=(n_axis+2)%3
    d[:,n_axis]=sign*z;d[:,a1]=x;d[:,a2]=y
    return d
def mean_B(axis,level,sign,m=2_000_000,E=0.0):
    o=rng.random((m,3));o[:,axis]=level
    # radiosity B = E + rho*H, H = pi * mean incoming radiance ; estimate incoming radiance via path tracing
    # L_in = L_e(hit) + rho * L_in(hit) recursively; with cosine sampling, H = pi*E[L]
    weight=np.ones(m); L=np.zeros(m)
    d=cosdir(axis,sign,m)
    for bounce in range(40):
        p,ax,lvl=trace(o,d)
        isfloor=(ax==1)&(lvl==0)
        L+=weight*np.where(isfloor,1/np.pi,0.0)
        weight*=rho
        nsign=np.where(lvl==0,1.0,-1.0)
        o=p
        # new cosine directions about inward normal of hit face
        dn=np.zeros((m,3))
        for a in range(3):
            sel=ax==a
            if sel.any():
                for s in (1.0,-1.0):
                    ss=sel&(nsign==s)
                    k=ss.sum()
                    if k: dn[ss]=cosdir(a,s,k)
        d=dn
        o=np.clip(o,1e-9,1-1e-9)
    H=np.pi*L.mean(); se=np.pi*L.std()/np.sqrt(m)
    return E+rho*H, rho*se
print('floor',mean_B(1,0,1,E=1.0))
print('ceiling',mean_B(1,1,-1))
print('side',mean_B(0,0,1))
