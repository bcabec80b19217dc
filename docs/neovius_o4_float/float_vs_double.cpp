#include "zero_set_points.h"
#include HEADER
#include <cstdio>
#include <cstdlib>
using namespace offsetgen::test;
#define CAT2(a,b) a##b
#define CAT(a,b) CAT2(a,b)
#define FN(s) CAT(P, s)
static void nrm(double x,double y,double z,double h,double*n){FN(_normal)(x,y,z,h,n);}
int main(int argc,char**argv){
  int N = argc>1?atoi(argv[1]):2000;
  CFunctions ref{&FN(_field),&FN(_offset),&FN(_shell),&nrm};
  unsigned seed = getenv("SEED")? (unsigned)atoi(getenv("SEED")) : 20261123u; auto pts = near_zero_set_points(ref.field, N, NAN, seed);
  double worst[3]={0,0,0}; int wi[3]={-1,-1,-1};
  int over=0;
  for(size_t i=0;i<pts.size();++i){
    float qf[3]={(float)pts[i].p[0],(float)pts[i].p[1],(float)pts[i].p[2]}; float hf=(float)pts[i].h;
    double q[3]={qf[0],qf[1],qf[2]}, h=hf;
    double g[3]; field_gradient(ref.field,q,g); double sc=length(g);
    double off = fabs(FN(_offsetf)(qf[0],qf[1],qf[2],hf) - ref.offset(q[0],q[1],q[2],h))/sc;
    double t=2*fabs(h);
    double shs = sc*(fabs(ref.offset(q[0],q[1],q[2],t/2))+fabs(ref.offset(q[0],q[1],q[2],-t/2)));
    double sh = fabs(FN(_shellf)(qf[0],qf[1],qf[2],(float)t) - ref.shell(q[0],q[1],q[2],t))/shs;
    double fi = fabs(FN(_fieldf)(qf[0],qf[1],qf[2]) - ref.field(q[0],q[1],q[2]))/sc;
    double v[3]={fi,off,sh};
    if (off>2e-5||sh>2e-5) { over++; if(getenv("LIST")) printf("i=%zu p=(%.6f %.6f %.6f) h=%.5f |gradF|=%.4f off=%.3e shell=%.3e\n",i,q[0],q[1],q[2],h,sc,off,sh);}
    for(int k=0;k<3;k++) if(v[k]>worst[k]){worst[k]=v[k];wi[k]=i;}
  }
  const char* nm[3]={"field","offset","shell"};
  for(int k=0;k<3;k++){ auto&z=pts[wi[k]]; double g[3]; field_gradient(ref.field,z.p,g);
    printf("%-6s worst %.3e at i=%d p=(%.6f %.6f %.6f) h=%.5f |gradF|=%.4f\n",nm[k],worst[k],wi[k],z.p[0],z.p[1],z.p[2],z.h,length(g));}
  printf("points over 2e-5: %d of %d\n",over,N);
}
