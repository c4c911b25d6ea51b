// The FrictVisco law's kernel (Law2_ScGeom_FrictViscoPhys_CundallStrackVisco::kernel) on two contacts at a time, one in each
// lane of lanes::Two, gives the bits of the scalar kernel on each contact (one lane sliding, the other sticking).
#include <gtest/gtest.h>
#include <pkg/dem/Law2_ScGeom_FrictViscoPhys_CundallStrackVisco.hpp>
#include <pkg/dem/TwoLanes.hpp>

using namespace yade;
using lanes::Two;

namespace {
struct Input {
    Real n[3], u, v[3], shearOld[3], du[3], kn, ks, cn, tanPhi;
};
struct Output {
    Real normalForce[3], normalViscous[3], shearForce[3], dissipated;
};
Output scalar(const Input& x) {
    Output o;
    Law2_ScGeom_FrictViscoPhys_CundallStrackVisco::kernel<Real>(x.n, x.u, x.v, x.shearOld, x.du, x.kn, x.ks, x.cn, x.tanPhi, o.normalForce,
            o.normalViscous, o.shearForce, o.dissipated);
    return o;
}
} // namespace

TEST(FrictViscoKernel, TwoLanesGiveTheScalarBits) {
    const Real s = std::sqrt(1 - 0.05 * 0.05);
    const Input a{{0.05, 0, s}, 2e-5, {0.3, 0.05, -0.5}, {-5, -1, 0.2}, {3e-7, 6e-8, -1e-8}, 1e5, 3e4, 17.4, std::tan(0.3)};
    const Input b{{0, 0.6, 0.8}, 1e-6, {-0.2, 0.1, 0.7}, {0.01, 0.002, -0.003}, {-1e-8, 2e-8, 0}, 2e5, 5e4, 30, std::tan(0.5)};
    const Output oa = scalar(a), ob = scalar(b);
    EXPECT_GT(oa.dissipated, 0); // lane 0 slides
    EXPECT_EQ(ob.dissipated, 0); // lane 1 sticks
    Two n[3], v[3], shearOld[3], du[3], normalForce[3], normalViscous[3], shearForce[3], dissipated;
    for (int i = 0; i < 3; ++i) {
        n[i] = Two(a.n[i], b.n[i]);
        v[i] = Two(a.v[i], b.v[i]);
        shearOld[i] = Two(a.shearOld[i], b.shearOld[i]);
        du[i] = Two(a.du[i], b.du[i]);
    }
    Law2_ScGeom_FrictViscoPhys_CundallStrackVisco::kernel<Two>(n, Two(a.u, b.u), v, shearOld, du, Two(a.kn, b.kn), Two(a.ks, b.ks),
            Two(a.cn, b.cn), Two(a.tanPhi, b.tanPhi), normalForce, normalViscous, shearForce, dissipated);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(normalForce[i].first(), oa.normalForce[i]);
        EXPECT_EQ(normalForce[i].second(), ob.normalForce[i]);
        EXPECT_EQ(normalViscous[i].first(), oa.normalViscous[i]);
        EXPECT_EQ(normalViscous[i].second(), ob.normalViscous[i]);
        EXPECT_EQ(shearForce[i].first(), oa.shearForce[i]);
        EXPECT_EQ(shearForce[i].second(), ob.shearForce[i]);
    }
    EXPECT_EQ(dissipated.first(), oa.dissipated);
    EXPECT_EQ(dissipated.second(), ob.dissipated);
}
