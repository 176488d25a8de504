#version 300 es
#define attribute in
#define varying out
#define texture2D texture
precision highp float ;
precision highp int ;
precision highp sampler2D ;
precision highp samplerCube ;
precision highp sampler3D ;
precision highp sampler2DArray ;
precision highp sampler2DShadow ;
precision highp samplerCubeShadow ;
precision highp sampler2DArrayShadow ;
precision highp isampler2D ;
precision highp isampler3D ;
precision highp isamplerCube ;
precision highp isampler2DArray ;
precision highp usampler2D ;
precision highp usampler3D ;
precision highp usamplerCube ;
precision highp usampler2DArray ;
#define HIGH_PRECISION
#define SHADER_TYPE ShadingMaterial
#define SHADER_NAME
#define SHADING_PHONG
#define LIGHTING_BLINN
#define CEL_BANDS 0
#define NUM_LIGHTS 1
#define HAS_NORMAL
uniform mat4 modelMatrix ;
uniform mat4 modelViewMatrix ;
uniform mat4 projectionMatrix ;
uniform mat4 viewMatrix ;
uniform mat3 normalMatrix ;
uniform vec3 cameraPosition ;
uniform bool isOrthographic ;
attribute vec3 position ;
attribute vec3 normal ;
attribute vec2 uv ;
#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#define saturate ( a ) clamp ( a , 0.0 , 1.0 )
#define whiteComplement ( a ) ( 1.0 - saturate ( a ) )
float pow2 ( const in float x ) { return x * x ; }
vec3 pow2 ( const in vec3 x ) { return x * x ; }
float pow3 ( const in float x ) { return x * x * x ; }
float pow4 ( const in float x ) { float x2 = x * x ; return x2 * x2 ; }
float max3 ( const in vec3 v ) { return max ( max ( v . x , v . y ) , v . z ) ; }
float average ( const in vec3 v ) { return dot ( v , vec3 ( 0.3333333 ) ) ; }
highp float rand ( const in vec2 uv ) {
const highp float a = 12.9898 , b = 78.233 , c = 43758.5453 ;
highp float dt = dot ( uv . xy , vec2 ( a , b ) ) , sn = mod ( dt , PI ) ;
return fract ( sin ( sn ) * c ) ;
}
float precisionSafeLength ( vec3 v ) { return length ( v ) ; }
struct IncidentLight {
vec3 color ;
vec3 direction ;
bool visible ;
} ;
struct ReflectedLight {
vec3 directDiffuse ;
vec3 directSpecular ;
vec3 indirectDiffuse ;
vec3 indirectSpecular ;
} ;
vec3 transformDirection ( in vec3 dir , in mat4 matrix ) {
return normalize ( ( matrix * vec4 ( dir , 0.0 ) ) . xyz ) ;
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix ( in vec3 normal , in mat4 viewMatrix ) {
return normalize ( ( vec4 ( normal , 0.0 ) * viewMatrix ) . xyz ) ;
}
vec3 transformDirectionByInverseViewMatrix ( in vec3 dir , in mat4 viewMatrix ) {
return normalize ( ( vec4 ( dir , 0.0 ) * viewMatrix ) . xyz ) ;
}
bool isPerspectiveMatrix ( mat4 m ) {
return m [ 2 ] [ 3 ] == - 1.0 ;
}
vec2 equirectUv ( in vec3 dir ) {
float u = atan ( dir . z , dir . x ) * RECIPROCAL_PI2 + 0.5 ;
float v = asin ( clamp ( dir . y , - 1.0 , 1.0 ) ) * RECIPROCAL_PI + 0.5 ;
return vec2 ( u , v ) ;
}
vec3 BRDF_Lambert ( const in vec3 diffuseColor ) {
return RECIPROCAL_PI * diffuseColor ;
}
vec3 F_Schlick ( const in vec3 f0 , const in float f90 , const in float dotVH ) {
float fresnel = exp2 ( ( - 5.55473 * dotVH - 6.98316 ) * dotVH ) ;
return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel ) ;
}
float F_Schlick ( const in float f0 , const in float f90 , const in float dotVH ) {
float fresnel = exp2 ( ( - 5.55473 * dotVH - 6.98316 ) * dotVH ) ;
return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel ) ;
}
uniform mat3 shadingNormalMatrix ;
out vec3 vWorldPosition ;
out vec3 vNormal ;
void main ( ) {
gl_Position = projectionMatrix * modelViewMatrix * vec4 ( position , 1.0 ) ;
vec3 objectNormal = normal ;
vec3 worldPosition = ( modelMatrix * vec4 ( position , 1.0 ) ) . xyz ;
vec3 worldNormal = shadingNormalMatrix * objectNormal ;
float normalLength = length ( worldNormal ) ;
vNormal = normalLength > 0.0 ? worldNormal / normalLength : vec3 ( 0.0 ) ;
vWorldPosition = worldPosition ;
}
----
#version 300 es
#define varying in
layout ( location = 0 ) out highp vec4 pc_fragColor ;
#define gl_FragColor pc_fragColor
#define gl_FragDepthEXT gl_FragDepth
#define texture2D texture
#define textureCube texture
#define texture2DProj textureProj
#define texture2DLodEXT textureLod
#define texture2DProjLodEXT textureProjLod
#define textureCubeLodEXT textureLod
#define texture2DGradEXT textureGrad
#define texture2DProjGradEXT textureProjGrad
#define textureCubeGradEXT textureGrad
precision highp float ;
precision highp int ;
precision highp sampler2D ;
precision highp samplerCube ;
precision highp sampler3D ;
precision highp sampler2DArray ;
precision highp sampler2DShadow ;
precision highp samplerCubeShadow ;
precision highp sampler2DArrayShadow ;
precision highp isampler2D ;
precision highp isampler3D ;
precision highp isamplerCube ;
precision highp isampler2DArray ;
precision highp usampler2D ;
precision highp usampler3D ;
precision highp usamplerCube ;
precision highp usampler2DArray ;
#define HIGH_PRECISION
#define SHADER_TYPE ShadingMaterial
#define SHADER_NAME
#define SHADING_PHONG
#define LIGHTING_BLINN
#define CEL_BANDS 0
#define NUM_LIGHTS 1
uniform mat4 viewMatrix ;
uniform vec3 cameraPosition ;
uniform bool isOrthographic ;
#define OPAQUE
vec4 LinearTransferOETF ( in vec4 value ) {
return value ;
}
vec4 sRGBTransferEOTF ( in vec4 value ) {
return vec4 ( mix ( pow ( value . rgb * 0.9478672986 + vec3 ( 0.0521327014 ) , vec3 ( 2.4 ) ) , value . rgb * 0.0773993808 , vec3 ( lessThanEqual ( value . rgb , vec3 ( 0.04045 ) ) ) ) , value . a ) ;
}
vec4 sRGBTransferOETF ( in vec4 value ) {
return vec4 ( mix ( pow ( value . rgb , vec3 ( 0.41666 ) ) * 1.055 - vec3 ( 0.055 ) , value . rgb * 12.92 , vec3 ( lessThanEqual ( value . rgb , vec3 ( 0.0031308 ) ) ) ) , value . a ) ;
}
vec4 linearToOutputTexel ( vec4 value ) {
return sRGBTransferOETF ( vec4 ( mat3 ( 1.0000 , 0.0000 , - 0.0000 , - 0.0000 , 1.0000 , - 0.0000 , - 0.0000 , 0.0000 , 1.0000 ) * value . rgb , value . a ) ) ;
}
float luminance ( const in vec3 rgb ) {
const vec3 weights = vec3 ( 0.2126 , 0.7152 , 0.0722 ) ;
return dot ( weights , rgb ) ;
}
in vec3 vWorldPosition ;
in vec3 vNormal ;
uniform vec4 shadingEye ;
uniform vec3 ambientTerm ;
uniform float shininess ;
uniform vec3 lightPosition [ NUM_LIGHTS ] ;
uniform vec3 lightDiffuse [ NUM_LIGHTS ] ;
uniform vec3 lightSpecular [ NUM_LIGHTS ] ;
#define LIGHT_ATTENUATION ( i ) vec3 ( 1.0 , 0.0 , 0.0 )
vec3 lightTerm ( vec3 p , vec3 n , vec3 v , vec3 lightPos , vec3 kdId , vec3 ksIs , vec3 k ) {
vec3 toLight = lightPos - p ;
float t2 = dot ( toLight , toLight ) ;
float invT = inversesqrt ( t2 ) ;
vec3 l = t2 > 0.0 ? toLight * invT : n ;
float ndl = dot ( n , l ) ;
float diffuse = max ( ndl , 0.0 ) ;
vec3 h = l + v ;
float h2 = dot ( h , h ) ;
float x = h2 > 0.0 ? max ( dot ( n , h ) * inversesqrt ( h2 ) , 0.0 ) : 0.0 ;
float spec = pow ( max ( x , 1e-30 ) , shininess ) ;
spec = x > 0.0 ? spec : step ( shininess , 0.0 ) ;
spec = ndl > 0.0 ? spec : 0.0 ;
return diffuse * kdId + spec * ksIs ;
}
vec3 shadeColor ( vec3 p , vec3 normal ) {
vec3 toEye = shadingEye . xyz - p * shadingEye . w ;
float e2 = dot ( toEye , toEye ) ;
vec3 v = e2 > 0.0 ? toEye * inversesqrt ( e2 ) : vec3 ( 0.0 , 0.0 , 1.0 ) ;
float n2 = dot ( normal , normal ) ;
vec3 n = n2 > 0.0 ? normal * inversesqrt ( n2 ) : v ;
v = e2 > 0.0 ? v : n ;
vec3 color = ambientTerm ;
color + = lightTerm ( p , n , v , lightPosition [ 0 ] , lightDiffuse [ 0 ] , lightSpecular [ 0 ] , LIGHT_ATTENUATION ( 0 ) ) ;
return color ;
}
void main ( ) {
vec3 color = shadeColor ( vWorldPosition , vNormal ) ;
gl_FragColor = vec4 ( color , 1.0 ) ;
gl_FragColor = linearToOutputTexel ( gl_FragColor ) ;
}
