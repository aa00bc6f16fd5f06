#pragma once
// The motor that drives a joint, as far as the joint's dynamics see it: its rotor
// inertia reflected through the gearbox. A rotor of inertia Jm behind a gear of ratio
// G (motor turns per joint turn, or motor radians per metre for a prismatic joint)
// spins at G q̇_j, so it adds ½ Jm G² q̇_j² to E_kin and Jm G² to b_jj: the armature of
// MuJoCo, the Jm·G² of the Robotics Toolbox. (The rotor's gyroscopic coupling with the
// links it rides on is neglected, as those tools do; with large G it is small beside
// Jm G².)
//
// It also keeps B regular where published tables leave the distal links light or
// without inertia: the motor's rotor still turns with the joint.
namespace ll {

struct JointMotor {
    // Jm [kg m²]; the armature itself when given as "armature" (then gearRatio is 1):
    // kg m² on a revolute joint, kg on a prismatic one.
    double inertia = 0.0;
    double gearRatio = 1.0;  // G; its sign (the turning direction) does not matter here
    bool fromMotor = false;  // written as "motor": {"inertia", "gear_ratio"}, else "armature"

    // Jm G², what the motor adds to b_jj [kg m² or kg].
    double armature() const { return inertia * gearRatio * gearRatio; }
};

}  // namespace ll
