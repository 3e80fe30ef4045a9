#version 330 core
in vec2 vCorner;
in float vStrength;
out vec4 fragColour;

void main()
{
    float r = length(vCorner);
    float alpha = 0.6 * vStrength * (1.0 - smoothstep(0.3, 1.0, r));
    if (alpha <= 0.0) discard;
    fragColour = vec4(0.0, 0.0, 0.0, alpha);
}
